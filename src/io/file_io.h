// SPDX-License-Identifier: MIT
// Whole-file reads and writes.
#pragma once

#include <cstdio>
#include <string>
#include <string_view>

namespace cgogn::io::detail
{

/// The whole content of the file at path, in one read. Throws io::Error when
/// the file cannot be opened or read. O(file size).
std::string read_file(const std::string& path);

/// Writes data to path in one write (replacing the file). Throws io::Error when
/// the file cannot be created or written. O(data size).
void write_file(const std::string& path, const std::string& data);

/// A file being written piece by piece (replacing the file). Every failure
/// throws io::Error naming the path.
class OutputFile
{
public:
	/// Creates or truncates the file at path.
	explicit OutputFile(const std::string& path);
	~OutputFile();
	OutputFile(const OutputFile&) = delete;
	OutputFile& operator=(const OutputFile&) = delete;
	/// Appends n bytes. O(n).
	void write(const char* bytes, std::size_t n);
	/// Flushes and closes the file; a write error that shows only now throws.
	void close();

private:
	std::string path_;
	std::FILE* file_ = nullptr;
};

/// A file's bytes, read-only, mapped into memory when the system can (no
/// copy: the pages are read as they are touched), else read whole. Throws
/// io::Error when the file cannot be opened or read.
class InputFile
{
public:
	explicit InputFile(const std::string& path);
	~InputFile();
	InputFile(const InputFile&) = delete;
	InputFile& operator=(const InputFile&) = delete;
	std::string_view bytes() const
	{
		return bytes_;
	}

private:
	std::string_view bytes_;
	void* mapping_ = nullptr;
	std::size_t mapped_size_ = 0;
	std::string read_; // the bytes, when the file was not mapped
};

} // namespace cgogn::io::detail
