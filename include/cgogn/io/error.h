// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/utils/error.h>

#include <cstdint>
#include <string>

namespace cgogn::io
{

/// A file could not be read or written. The message names the file, where the
/// problem is (line for text formats, byte offset for binary ones, nothing for
/// problems of the whole file) and the cause, e.g.
/// `bunny.off:12: vertex index 40 out of range (the file has 35 vertices)`.
class Error : public cgogn::Error
{
public:
	/// Where in the file the problem is.
	enum class Where
	{
		File, ///< the whole file (no position)
		Line, ///< a line of a text format
		Byte  ///< a byte offset of a binary format
	};

	/// A problem of the whole file (cannot open it, unknown format, ...).
	Error(const std::string& path, const std::string& cause)
		: cgogn::Error(path + ": " + cause), path_(path), cause_(cause)
	{
	}
	/// A problem at a line (Where::Line) or byte offset (Where::Byte).
	Error(const std::string& path, Where where, std::uint64_t position, const std::string& cause)
		: cgogn::Error(path +
					   (where == Where::Line   ? ":"
						: where == Where::Byte ? ": byte "
											   : "") +
					   (where == Where::File ? std::string() : std::to_string(position)) + ": " + cause),
		  path_(path), cause_(cause), where_(where), position_(position)
	{
	}

	/// The file's path, as given to the load or save function.
	const std::string& path() const
	{
		return path_;
	}
	/// The problem alone, without path and position.
	const std::string& cause() const
	{
		return cause_;
	}
	/// Whether position() is a line, a byte offset or meaningless (File).
	Where where() const
	{
		return where_;
	}
	/// The line (1-based) or byte offset (0-based) of the problem.
	std::uint64_t position() const
	{
		return position_;
	}

private:
	std::string path_;
	std::string cause_;
	Where where_ = Where::File;
	std::uint64_t position_ = 0;
};

} // namespace cgogn::io
