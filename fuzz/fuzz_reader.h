// SPDX-License-Identifier: MIT
// The reader fuzzing body shared by every libFuzzer target (fuzz_reader.cpp).
#pragma once

#include <cstddef>
#include <cstdint>

namespace cgogn_fuzz
{

/// The format argument that makes the input's first byte choose the reader
/// and loads into a map already holding a mesh and attributes.
inline constexpr int append_mode = -1;

/// Runs one fuzzing input through the reader of `format` (the index of a
/// format in fuzz/CMakeLists.txt's list) or, with append_mode, of the reader
/// the first byte chooses. Aborts on any broken invariant; returns 0.
int run_one_input(int format, const std::uint8_t* data, std::size_t size);

} // namespace cgogn_fuzz
