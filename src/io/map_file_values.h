// SPDX-License-Identifier: MIT
// The value types of the .cgmap format: their names and their little-endian
// encodings.
#pragma once

#include <cgogn/core/attributes/attribute_container.h>
#include <cgogn/geometry/types/vector_traits.h>

#include "byte_reader.h"
#include "file_io.h"

#include <array>
#include <bit>
#include <cstring>
#include <string>
#include <tuple>
#include <typeindex>
#include <vector>

namespace cgogn::io::detail
{

/// Where a .cgmap file's bytes go: a string (save_map_to_bytes), or a file
/// through a buffer of 1 MB, which large runs of values bypass (save_map: no
/// copy of the whole file in memory).
class ByteSink
{
public:
	/// Appends to `out`.
	explicit ByteSink(std::string& out) : out_(out)
	{
	}
	/// Writes to `file`.
	explicit ByteSink(OutputFile& file) : out_(buffer_), file_(&file)
	{
		buffer_.reserve(BUFFER_SIZE);
	}
	void append(const char* bytes, std::size_t n)
	{
		if (file_ != nullptr && out_.size() + n > BUFFER_SIZE)
		{
			flush();
			if (n >= BUFFER_SIZE)
			{
				file_->write(bytes, n);
				return;
			}
		}
		out_.append(bytes, n);
	}
	void append(std::string_view s)
	{
		append(s.data(), s.size());
	}
	/// Writes what the buffer holds to the file (nothing for a string).
	/// Throws io::Error when the file cannot be written.
	void flush()
	{
		if (file_ != nullptr && !out_.empty())
		{
			file_->write(out_.data(), out_.size());
			out_.clear();
		}
	}

private:
	static constexpr std::size_t BUFFER_SIZE = std::size_t(1) << 20;

	std::string buffer_;
	std::string& out_;
	OutputFile* file_ = nullptr;
};

/// Appends the little-endian bytes of a scalar.
template <typename S>
void put_scalar(ByteSink& out, S v)
{
	char b[sizeof(S)];
	std::memcpy(b, &v, sizeof(S));
	if constexpr (std::endian::native == std::endian::big)
		for (std::size_t i = 0; i < sizeof(S) / 2; ++i)
			std::swap(b[i], b[sizeof(S) - 1 - i]);
	out.append(b, sizeof(S));
}

/// A length-prefixed string: uint32 byte count, then the bytes.
inline void put_string(ByteSink& out, std::string_view s)
{
	put_scalar<uint32>(out, uint32(s.size()));
	out.append(s);
}

/// Reads a length-prefixed string, refusing one longer than what remains.
inline std::string get_string(ByteReader& in)
{
	const uint32 n = in.read<uint32>();
	in.check_count(n, 1, "string bytes");
	std::string s(n, '\0');
	for (uint32 i = 0; i < n; ++i)
		s[i] = in.read<char>();
	return s;
}

template <typename S>
struct ScalarName;
#define CGOGN_SCALAR_NAME(TYPE, NAME)                                                                                  \
	template <>                                                                                                        \
	struct ScalarName<TYPE>                                                                                            \
	{                                                                                                                  \
		static constexpr const char* name = NAME;                                                                      \
	};
CGOGN_SCALAR_NAME(bool, "bool")
CGOGN_SCALAR_NAME(int8, "int8")
CGOGN_SCALAR_NAME(uint8, "uint8")
CGOGN_SCALAR_NAME(std::int16_t, "int16")
CGOGN_SCALAR_NAME(uint16, "uint16")
CGOGN_SCALAR_NAME(int32, "int32")
CGOGN_SCALAR_NAME(uint32, "uint32")
CGOGN_SCALAR_NAME(int64, "int64")
CGOGN_SCALAR_NAME(uint64, "uint64")
CGOGN_SCALAR_NAME(float, "float32")
CGOGN_SCALAR_NAME(double, "float64")
#undef CGOGN_SCALAR_NAME

/// How a value type is named, written and read. Scalars are their bytes
/// (bool: one byte, 0 or 1); vectors and arrays their coordinates in order;
/// strings length-prefixed.
template <typename T>
struct ValueCodec
{
	static std::string name()
	{
		return ScalarName<T>::name;
	}
	static std::size_t size(const T&)
	{
		return std::is_same_v<T, bool> ? 1 : sizeof(T);
	}
	static void write(ByteSink& out, const T& v)
	{
		if constexpr (std::is_same_v<T, bool>)
			put_scalar<uint8>(out, v ? 1 : 0);
		else
			put_scalar<T>(out, v);
	}
	static T read(ByteReader& in)
	{
		if constexpr (std::is_same_v<T, bool>)
		{
			const uint8 b = in.read<uint8>();
			if (b > 1)
				in.fail("a bool value is " + std::to_string(b) + ", not 0 or 1");
			return b == 1;
		}
		else
			return in.read<T>();
	}
};

template <int N>
struct ValueCodec<Eigen::Matrix<double, N, 1>>
{
	using T = Eigen::Matrix<double, N, 1>;
	static std::string name()
	{
		return "Vec" + std::to_string(N);
	}
	static std::size_t size(const T&)
	{
		return N * sizeof(double);
	}
	static void write(ByteSink& out, const T& v)
	{
		for (int i = 0; i < N; ++i)
			put_scalar<double>(out, v[i]);
	}
	static T read(ByteReader& in)
	{
		T v;
		for (int i = 0; i < N; ++i)
			v[i] = in.read<double>();
		return v;
	}
};

template <typename S, std::size_t K>
struct ValueCodec<std::array<S, K>>
{
	static std::string name()
	{
		return std::string(ScalarName<S>::name) + "[" + std::to_string(K) + "]";
	}
	static std::size_t size(const std::array<S, K>&)
	{
		return K * sizeof(S);
	}
	static void write(ByteSink& out, const std::array<S, K>& v)
	{
		for (const S& x : v)
			put_scalar<S>(out, x);
	}
	static std::array<S, K> read(ByteReader& in)
	{
		std::array<S, K> v;
		for (S& x : v)
			x = in.read<S>();
		return v;
	}
};

template <>
struct ValueCodec<std::string>
{
	static std::string name()
	{
		return "string";
	}
	static std::size_t size(const std::string& v)
	{
		return sizeof(uint32) + v.size();
	}
	static void write(ByteSink& out, const std::string& v)
	{
		put_string(out, v);
	}
	static std::string read(ByteReader& in)
	{
		return get_string(in);
	}
};

/// What reading one attribute of the file needs: where its values go and
/// what the map already has under its name.
struct AttributeRead
{
	ByteReader& in;
	AttributeContainer& container;
	Orbit orbit;                          ///< the container's orbit
	const std::string& name;              ///< the attribute's name
	std::shared_ptr<AttributeBase> found; ///< the map's own attribute of that name (nullptr: create one)
	uint32 end;                           ///< the container's lines
};

/// The typed work on attributes, for the types of a group: the groups are
/// compiled apart (map_file_scalars.cpp, map_file_vectors.cpp), each of its
/// types creating its attribute class for every orbit.
template <typename TYPES>
struct AttributeValues;
template <typename... T>
struct AttributeValues<std::tuple<T...>>
{
	/// Appends an attribute's format type name, payload size, default value
	/// and the values of lines [0, end).
	using Writer = void (*)(ByteSink& out, const AttributeBase& a, uint32 end);
	/// The writer of `a`'s type; nullptr when its type is not one of the group.
	static Writer writer(const AttributeBase& a);
	/// Reads the default value and the values of an attribute of the type
	/// named `type` into r.found, or into a new attribute of r.container;
	/// false (nothing read) when the type is not one of the group. Throws
	/// io::Error when r.found has another type.
	static bool read(AttributeRead& r, std::string_view type);
	/// The format's names of the group's types.
	static void names(std::vector<std::string>& out)
	{
		(out.push_back(ValueCodec<T>::name()), ...);
	}
	/// The format's name of a's value type; empty when it is not one of the group's.
	static std::string name_of(const AttributeBase& a)
	{
		std::string name;
		(void)((a.type() == typeid(T) ? (name = ValueCodec<T>::name(), true) : false) || ...);
		return name;
	}
};

/// The groups of the format's value types (map_file_value_types() lists them).
using ScalarValueTypes =
	std::tuple<bool, int8, uint8, std::int16_t, uint16, int32, uint32, int64, uint64, float, double>;
using VectorValueTypes = std::tuple<Vec2, Vec3, Vec4, std::array<double, 1>, std::array<double, 2>,
									std::array<double, 3>, std::array<double, 4>, std::array<double, 5>,
									std::array<double, 6>, std::array<double, 7>, std::array<double, 8>, std::string>;

} // namespace cgogn::io::detail
