// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/utils/numeric.h>

#include <cstddef>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

namespace cgogn::dist::detail
{

/// What the root sends one rank: its top cells (owned and ghost) as a cell
/// soup over local vertex numbers, with the global id and owner of every
/// vertex, of every top cell, and of the edges (and faces) of every corner.
struct PartMessage
{
	std::vector<uint64> vertex_gid;
	std::vector<int32> vertex_owner;
	std::vector<uint64> cell_gid;
	std::vector<int32> cell_owner;
	std::vector<uint32> cell_nb_faces; ///< Faces of each volume (empty for surfaces).
	std::vector<uint32> face_sizes;    ///< Corners of each face, face after face.
	std::vector<uint32> corner_vertex; ///< The local vertex of each corner (a face's corners in phi1 order).
	/// Per corner, the cell of dimension k + 1 (the edge, then the face of a
	/// volume) of the dart leaving the corner's vertex in its face.
	std::vector<uint64> corner_gid[2];
	std::vector<int32> corner_owner[2];
	/// The attributes of the vertices and of the top cells, in the order of
	/// the vertices and cells above.
	struct Column
	{
		std::string name;
		uint8 of_top_cells = 0; ///< 0: a vertex attribute, 1: a top cell attribute.
		uint8 type = 0;         ///< Index in the list of types distribute() carries.
		std::vector<std::byte> values;
	};
	std::vector<Column> columns;
	/// The attributes of the root's map that distribute() did not carry.
	std::vector<std::string> not_carried;
};

/// Appends vectors to a byte buffer, each after its length.
class ByteWriter
{
public:
	template <typename T>
	void put(const std::vector<T>& v)
	{
		const uint64 n = v.size();
		append(&n, sizeof n);
		append(v.data(), n * sizeof(T));
	}
	void put(const std::string& text)
	{
		put(std::vector<char>(text.begin(), text.end()));
	}
	std::vector<std::byte>& bytes()
	{
		return bytes_;
	}

private:
	void append(const void* p, std::size_t n)
	{
		const std::size_t at = bytes_.size();
		bytes_.resize(at + n);
		if (n != 0)
			std::memcpy(bytes_.data() + at, p, n);
	}
	std::vector<std::byte> bytes_;
};

/// Reads back what a ByteWriter wrote, in the same order.
class ByteReader
{
public:
	explicit ByteReader(const std::vector<std::byte>& bytes) : bytes_(bytes)
	{
	}
	template <typename T>
	void get(std::vector<T>& v)
	{
		uint64 n = 0;
		take(&n, sizeof n);
		v.resize(n);
		take(v.data(), n * sizeof(T));
	}
	void get(std::string& text)
	{
		std::vector<char> chars;
		get(chars);
		text.assign(chars.begin(), chars.end());
	}

private:
	void take(void* p, std::size_t n)
	{
		if (at_ + n > bytes_.size())
			throw std::runtime_error("distribute: truncated part message");
		if (n != 0)
			std::memcpy(p, bytes_.data() + at_, n);
		at_ += n;
	}
	const std::vector<std::byte>& bytes_;
	std::size_t at_ = 0;
};

// Calls f on each array of a message, in the order of the bytes.
template <typename MESSAGE, typename F>
void foreach_array(MESSAGE& m, const F& f)
{
	f(m.vertex_gid);
	f(m.vertex_owner);
	f(m.cell_gid);
	f(m.cell_owner);
	f(m.cell_nb_faces);
	f(m.face_sizes);
	f(m.corner_vertex);
	for (int k = 0; k < 2; ++k)
	{
		f(m.corner_gid[k]);
		f(m.corner_owner[k]);
	}
}

inline std::vector<std::byte> serialize(const PartMessage& m)
{
	ByteWriter w;
	foreach_array(m, [&](const auto& v) { w.put(v); });
	w.put(std::vector<uint64>{m.columns.size(), m.not_carried.size()});
	for (const PartMessage::Column& c : m.columns)
	{
		w.put(c.name);
		w.put(std::vector<uint8>{c.of_top_cells, c.type});
		w.put(c.values);
	}
	for (const std::string& name : m.not_carried)
		w.put(name);
	return std::move(w.bytes());
}

inline PartMessage deserialize(const std::vector<std::byte>& bytes)
{
	PartMessage m;
	ByteReader r(bytes);
	foreach_array(m, [&](auto& v) { r.get(v); });
	std::vector<uint64> sizes;
	r.get(sizes);
	if (sizes.size() != 2)
		throw std::runtime_error("distribute: malformed part message");
	m.columns.resize(sizes[0]);
	for (PartMessage::Column& c : m.columns)
	{
		r.get(c.name);
		std::vector<uint8> kind;
		r.get(kind);
		if (kind.size() != 2)
			throw std::runtime_error("distribute: malformed part message");
		c.of_top_cells = kind[0];
		c.type = kind[1];
		r.get(c.values);
	}
	m.not_carried.resize(sizes[1]);
	for (std::string& name : m.not_carried)
		r.get(name);
	return m;
}

} // namespace cgogn::dist::detail
