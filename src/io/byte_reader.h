// SPDX-License-Identifier: MIT
// Bounds-checked reads of little- or big-endian binary values.
#pragma once

#include <cgogn/core/utils/numeric.h>
#include <cgogn/io/error.h>

#include <bit>
#include <cstring>
#include <string>
#include <string_view>

namespace cgogn::io::detail
{

class ByteReader
{
public:
	ByteReader(std::string_view data, std::size_t start, const std::string& path, bool big_endian)
		: data_(data), pos_(start), path_(path), swap_(big_endian != (std::endian::native == std::endian::big))
	{
	}

	template <typename T>
	T read()
	{
		if (sizeof(T) > data_.size() - pos_)
			fail("unexpected end of file (truncated binary data)");
		T v;
		if (swap_)
		{
			char b[sizeof(T)];
			for (std::size_t i = 0; i < sizeof(T); ++i)
				b[i] = data_[pos_ + sizeof(T) - 1 - i];
			std::memcpy(&v, b, sizeof(T));
		}
		else
			std::memcpy(&v, data_.data() + pos_, sizeof(T));
		pos_ += sizeof(T);
		return v;
	}
	/// Copies the next n bytes as they are (no byte swap) to `to`.
	void read_bytes(char* to, std::size_t n)
	{
		if (n > data_.size() - pos_)
			fail("unexpected end of file (truncated binary data)");
		std::memcpy(to, data_.data() + pos_, n);
		pos_ += n;
	}
	void skip(std::size_t n)
	{
		if (n > data_.size() - pos_)
			fail("unexpected end of file (truncated binary data)");
		pos_ += n;
	}
	std::size_t position() const
	{
		return pos_;
	}
	std::size_t remaining() const
	{
		return data_.size() - pos_;
	}
	[[noreturn]] void fail(const std::string& cause) const
	{
		throw Error(path_, Error::Where::Byte, pos_, cause);
	}
	/// Throws unless `count` records of `bytes` bytes each fit in what remains.
	void check_count(uint64 count, uint64 bytes, const char* what) const
	{
		if (count > uint64(INVALID_INDEX) - 1 || (bytes > 0 && count > remaining() / bytes))
			fail("declared " + std::to_string(count) + " " + what + " but only " + std::to_string(remaining()) +
				 " bytes remain in the file");
	}

private:
	std::string_view data_;
	std::size_t pos_;
	const std::string& path_;
	bool swap_;
};

} // namespace cgogn::io::detail
