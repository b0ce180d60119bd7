// SPDX-License-Identifier: MIT
// The entry point of one libFuzzer target: CGOGN_FUZZ_FORMAT names its reader
// (or cgogn_fuzz::append_mode). The body, fuzz_reader.cpp, is compiled once
// for all the targets.
#include "fuzz_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
	return cgogn_fuzz::run_one_input(CGOGN_FUZZ_FORMAT, data, size);
}
