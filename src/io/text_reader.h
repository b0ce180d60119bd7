// SPDX-License-Identifier: MIT
// A line-counting tokenizer over a whole file held in memory. Numbers are
// parsed with std::from_chars (no locale, no iostream).
#pragma once

#include <cgogn/core/utils/numeric.h>
#include <cgogn/io/error.h>

#include <charconv>
#include <cmath>
#include <string>
#include <string_view>

namespace cgogn::io::detail
{

class TextReader
{
public:
	/// `comment`: the character that starts a comment running to the end of the
	/// line ('\0' for none).
	TextReader(std::string_view text, const std::string& path, char comment = '#', uint64 first_line = 1)
		: p_(text.data()), end_(text.data() + text.size()), path_(path), comment_(comment), line_(first_line)
	{
	}

	/// Skips spaces, newlines and comments.
	void skip_space()
	{
		while (p_ < end_)
		{
			const char c = *p_;
			if (c == '\n')
			{
				++line_;
				++p_;
			}
			else if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v')
				++p_;
			else if (comment_ != '\0' && c == comment_)
			{
				while (p_ < end_ && *p_ != '\n')
					++p_;
			}
			else
				return;
		}
	}
	/// Skips spaces and tabs (and a comment) but stops at the end of the line.
	void skip_blank()
	{
		while (p_ < end_ && (*p_ == ' ' || *p_ == '\t' || *p_ == '\r' || *p_ == '\f' || *p_ == '\v'))
			++p_;
		if (comment_ != '\0' && p_ < end_ && *p_ == comment_)
			while (p_ < end_ && *p_ != '\n')
				++p_;
	}
	/// True at the end of the text (after skipping spaces and comments).
	bool at_end()
	{
		skip_space();
		return p_ >= end_;
	}
	/// True when nothing but spaces or a comment remains on this line.
	bool at_eol()
	{
		skip_blank();
		return p_ >= end_ || *p_ == '\n';
	}
	/// Moves to the beginning of the next line.
	void next_line()
	{
		while (p_ < end_ && *p_ != '\n')
			++p_;
		if (p_ < end_)
		{
			++p_;
			++line_;
		}
	}
	/// The rest of the current line (without the newline), and moves past it.
	std::string_view rest_of_line()
	{
		const char* b = p_;
		while (p_ < end_ && *p_ != '\n')
			++p_;
		std::string_view s(b, std::size_t(p_ - b));
		if (!s.empty() && s.back() == '\r')
			s.remove_suffix(1);
		return s;
	}
	/// The next whitespace-separated token, across lines; empty at the end.
	std::string_view token()
	{
		skip_space();
		return raw_token();
	}
	/// The next token on the current line; empty at the end of the line.
	std::string_view token_in_line()
	{
		skip_blank();
		return raw_token();
	}

	/// Parses the next token (across lines) as a finite double.
	double read_double(const char* what)
	{
		return to_double(token(), what);
	}
	/// Parses the next token (across lines) as an unsigned 32-bit integer.
	uint32 read_uint(const char* what)
	{
		return to_uint(token(), what);
	}
	/// Parses the next token (across lines) as a signed 64-bit integer.
	int64 read_int(const char* what)
	{
		return to_int(token(), what);
	}

	double to_double(std::string_view t, const char* what) const
	{
		if (t.empty())
			fail(std::string("unexpected end of file, expected ") + what);
		const char* b = t.data();
		const char* e = b + t.size();
		if (*b == '+')
			++b;
		double v = 0.0;
		auto [ptr, ec] = std::from_chars(b, e, v);
		if (ec != std::errc() || ptr != e)
		{
			if (ec == std::errc::result_out_of_range)
				fail(std::string(what) + " out of the range of double: '" + printable(t) + "'");
			fail(std::string("expected ") + what + ", found '" + printable(t) + "'");
		}
		if (!std::isfinite(v))
			fail(std::string(what) + " is not finite ('" + printable(t) + "'): NaN and infinite values are rejected");
		return v;
	}
	uint32 to_uint(std::string_view t, const char* what) const
	{
		const int64 v = to_int(t, what);
		if (v < 0 || v > int64(INVALID_INDEX) - 1)
			fail(std::string(what) + " out of range: " + std::to_string(v));
		return uint32(v);
	}
	int64 to_int(std::string_view t, const char* what) const
	{
		if (t.empty())
			fail(std::string("unexpected end of file, expected ") + what);
		const char* b = t.data();
		const char* e = b + t.size();
		if (*b == '+')
			++b;
		int64 v = 0;
		auto [ptr, ec] = std::from_chars(b, e, v);
		if (ec != std::errc() || ptr != e)
			fail(std::string("expected ") + what + " (an integer), found '" + printable(t) + "'");
		return v;
	}

	/// Throws io::Error at the current line.
	[[noreturn]] void fail(const std::string& cause) const
	{
		throw Error(path_, Error::Where::Line, line_, cause);
	}

	uint64 line() const
	{
		return line_;
	}
	/// Bytes left to read: caps declared counts (every item needs some bytes).
	std::size_t remaining() const
	{
		return std::size_t(end_ - p_);
	}
	const char* position() const
	{
		return p_;
	}
	void set_position(const char* p)
	{
		p_ = p;
	}
	const std::string& path() const
	{
		return path_;
	}

	/// Throws unless `count` items of at least `min_bytes` bytes each fit in
	/// the rest of the file: a declared count cannot make us allocate more than
	/// the file could describe. `min_bytes` counts an item's separator, which
	/// the last item may lack (`<DataArray ...>4</DataArray>`, a file without a
	/// final newline): one byte less is accepted.
	void check_count(uint64 count, uint64 min_bytes, const char* what) const
	{
		if (count > uint64(INVALID_INDEX) - 1 || count * min_bytes > remaining() + 1)
			fail("declared " + std::to_string(count) + " " + what + " but only " + std::to_string(remaining()) +
				 " bytes remain in the file");
	}

	/// A token made safe for an error message (non-printable bytes as '?', cut to 40).
	static std::string printable(std::string_view t)
	{
		std::string s;
		for (char c : t.substr(0, 40))
			s += (c >= 32 && c < 127) ? c : '?';
		if (t.size() > 40)
			s += "...";
		return s;
	}

private:
	std::string_view raw_token()
	{
		const char* b = p_;
		while (p_ < end_)
		{
			const char c = *p_;
			if (c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v' ||
				(comment_ != '\0' && c == comment_))
				break;
			++p_;
		}
		return std::string_view(b, std::size_t(p_ - b));
	}

	const char* p_;
	const char* end_;
	const std::string& path_;
	char comment_;
	uint64 line_;
};

} // namespace cgogn::io::detail
