// SPDX-License-Identifier: MIT
// Appending numbers to a text buffer with std::to_chars (shortest form that
// reads back to the same double).
#pragma once

#include <cgogn/core/utils/numeric.h>

#include <bit>
#include <charconv>
#include <string>

namespace cgogn::io::detail
{

inline void append_double(std::string& s, double v)
{
	char buf[32];
	auto r = std::to_chars(buf, buf + sizeof(buf), v);
	s.append(buf, r.ptr);
}
inline void append_uint(std::string& s, uint64 v)
{
	char buf[24];
	auto r = std::to_chars(buf, buf + sizeof(buf), v);
	s.append(buf, r.ptr);
}
inline void append_int(std::string& s, int64 v)
{
	char buf[24];
	auto r = std::to_chars(buf, buf + sizeof(buf), v);
	s.append(buf, r.ptr);
}
/// Appends the bytes of v in little-endian order.
template <typename T>
void append_raw(std::string& s, T v)
{
	const char* b = reinterpret_cast<const char*>(&v);
	if constexpr (std::endian::native == std::endian::little)
		s.append(b, sizeof(T));
	else
		for (std::size_t i = sizeof(T); i-- > 0;)
			s.push_back(b[i]);
}
/// Appends the bytes of v in big-endian order.
template <typename T>
void append_raw_be(std::string& s, T v)
{
	const char* b = reinterpret_cast<const char*>(&v);
	if constexpr (std::endian::native == std::endian::big)
		s.append(b, sizeof(T));
	else
		for (std::size_t i = sizeof(T); i-- > 0;)
			s.push_back(b[i]);
}

} // namespace cgogn::io::detail
