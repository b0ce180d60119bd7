// SPDX-License-Identifier: MIT
// Whole-file reads and writes.
#pragma once

#include <string>

namespace cgogn::io::detail
{

/// The whole content of the file at path, in one read. Throws io::Error when
/// the file cannot be opened or read. O(file size).
std::string read_file(const std::string& path);

/// Writes data to path in one write (replacing the file). Throws io::Error when
/// the file cannot be created or written. O(data size).
void write_file(const std::string& path, const std::string& data);

} // namespace cgogn::io::detail
