// SPDX-License-Identifier: MIT
// VTK legacy unstructured grids (.vtk), ascii and binary (big endian), with
// the classic CELLS layout and the 5.x OFFSETS/CONNECTIVITY one. Volume cells
// (tetra 10, voxel 11, hexahedron 12, wedge 13, pyramid 14, and the corner
// nodes of quadratic tetra 24 / hexahedron 25) are kept; lower-dimensional
// cells are ignored. POINT_DATA and CELL_DATA arrays of 1 to 3 components
// (SCALARS, VECTORS, NORMALS, FIELD) become columns, of their integer type
// when they have one.
#include "byte_reader.h"
#include "formats.h"
#include "text_reader.h"
#include "text_writer.h"
#include "value_type_names.h"
#include "vtk_cells.h"

#include <array>
#include <cmath>

namespace cgogn::io::detail
{

namespace
{

class VtkReader
{
public:
	VtkReader(std::string_view data, const std::string& path) : data_(data), t_(data, path, '\0'), path_(path)
	{
	}

	MeshData read()
	{
		std::string_view l = t_.rest_of_line();
		if (l.substr(0, 14) != "# vtk DataFile")
			t_.fail("not a VTK legacy file: it does not start with '# vtk DataFile'");
		t_.next_line();
		t_.rest_of_line(); // title
		t_.next_line();
		const std::string_view mode = t_.token();
		if (mode == "BINARY")
			binary_ = true;
		else if (mode != "ASCII")
			t_.fail("expected ASCII or BINARY, found '" + TextReader::printable(mode) + "'");
		if (t_.token() != "DATASET" || t_.token() != "UNSTRUCTURED_GRID")
			t_.fail("only DATASET UNSTRUCTURED_GRID is read");

		std::vector<int64> offsets, connectivity, types;
		bool have_points = false, have_cells = false, have_types = false;
		std::vector<Column>* data_target = nullptr;
		std::vector<std::string>* data_names = nullptr;
		uint64 data_count = 0;
		while (true)
		{
			const std::string_view k = t_.token();
			if (k.empty())
				break;
			if (k == "POINTS")
			{
				const uint32 n = t_.read_uint("a point count");
				const std::string_view type = t_.token();
				std::vector<double> v;
				read_array(uint64(n) * 3, type, v, true);
				d_.positions = std::move(v);
				have_points = true;
			}
			else if (k == "CELLS")
			{
				const uint32 a = t_.read_uint("a cell count");
				const uint32 b = t_.read_uint("a cell list size");
				const char* save = t_.position();
				if (t_.token() == "OFFSETS")
				{
					// 5.x: OFFSETS type <a values> CONNECTIVITY type <b values>
					std::vector<double> v;
					read_array(a, t_.token(), v, false);
					offsets = to_int64(v);
					if (t_.token() != "CONNECTIVITY")
						t_.fail("expected CONNECTIVITY after OFFSETS");
					read_array(b, t_.token(), v, false);
					connectivity = to_int64(v);
					if (offsets.empty() || offsets.front() != 0 || offsets.back() != int64(b))
						t_.fail("inconsistent OFFSETS");
				}
				else
				{
					t_.set_position(save);
					std::vector<double> v;
					read_array(b, "int", v, false);
					offsets.push_back(0);
					std::size_t i = 0;
					for (uint32 c = 0; c < a; ++c)
					{
						if (i >= v.size() || v[i] < 0 || v[i] > double(v.size() - i - 1))
							t_.fail("cell " + std::to_string(c) + " runs past the CELLS list");
						const std::size_t n = std::size_t(v[i]);
						for (std::size_t j = i + 1; j < i + 1 + n; ++j)
							connectivity.push_back(to_int64(v[j]));
						i += n + 1;
						offsets.push_back(int64(connectivity.size()));
					}
					if (i != v.size())
						t_.fail("the CELLS list is longer than its cells");
				}
				have_cells = true;
			}
			else if (k == "CELL_TYPES")
			{
				const uint32 n = t_.read_uint("a cell count");
				std::vector<double> v;
				read_array(n, "int", v, false);
				types = to_int64(v);
				have_types = true;
			}
			else if (k == "POINT_DATA" || k == "CELL_DATA")
			{
				data_count = t_.read_uint("a data count");
				data_target = k == "POINT_DATA" ? &d_.vertex_columns : &cell_data_;
				data_names = k == "POINT_DATA" ? &point_data_names_ : &cell_data_names_;
			}
			else if (k == "SCALARS" || k == "VECTORS" || k == "NORMALS" || k == "COLOR_SCALARS" ||
					 k == "TEXTURE_COORDINATES" || k == "TENSORS")
			{
				if (!data_target)
					t_.fail(std::string(k) + " outside POINT_DATA or CELL_DATA");
				const std::string name(t_.token());
				uint32 dim = 3;
				std::string_view type = "float";
				if (k == "SCALARS")
				{
					type = t_.token();
					dim = 1;
					if (!t_.at_eol())
						dim = t_.to_uint(t_.token_in_line(), "a component count");
					const char* save = t_.position();
					if (t_.token() == "LOOKUP_TABLE")
						t_.token();
					else
						t_.set_position(save);
				}
				else if (k == "COLOR_SCALARS")
				{
					dim = t_.read_uint("a component count");
					type = binary_ ? "unsigned_char" : "float";
				}
				else if (k == "TEXTURE_COORDINATES")
				{
					dim = t_.read_uint("a dimension");
					type = t_.token();
				}
				else if (k == "TENSORS")
				{
					dim = 9;
					type = t_.token();
				}
				else
					type = t_.token();
				add_data(*data_target, *data_names, data_target == &d_.vertex_columns, name, dim, data_count, type);
			}
			else if (k == "FIELD")
			{
				if (!data_target)
					t_.fail("FIELD outside POINT_DATA or CELL_DATA");
				t_.token();
				const uint32 arrays = t_.read_uint("an array count");
				for (uint32 i = 0; i < arrays; ++i)
				{
					const std::string name(t_.token());
					const uint32 dim = t_.read_uint("a component count");
					const uint32 n = t_.read_uint("a tuple count");
					add_data(*data_target, *data_names, data_target == &d_.vertex_columns, name, dim, n, t_.token());
				}
			}
			else if (k == "LOOKUP_TABLE")
			{
				t_.token();
				const uint32 n = t_.read_uint("a table size");
				std::vector<double> v;
				read_array(uint64(n) * 4, binary_ ? "unsigned_char" : "float", v, false);
			}
			else if (k == "METADATA")
			{
				// skipped up to the next empty line
				t_.next_line();
				while (t_.remaining() > 0 && !t_.rest_of_line().empty())
					t_.next_line();
			}
			else
				t_.fail("unsupported VTK keyword '" + TextReader::printable(k) + "'");
		}
		if (!have_points || !have_cells || !have_types)
			t_.fail("incomplete unstructured grid: POINTS, CELLS and CELL_TYPES are needed");
		if (types.size() + 1 != offsets.size())
			t_.fail("CELL_TYPES and CELLS do not have the same number of cells");
		vtk_cells_to_mesh(d_, offsets, connectivity, types, cell_data_, [&](const std::string& m) { t_.fail(m); });
		return std::move(d_);
	}

private:
	void read_array(uint64 count, std::string_view type, std::vector<double>& out, bool finite)
	{
		// the type, once: float is read as float and held as a double
		const std::optional<ValueType> stored = vtk_legacy_value_type(type);
		if (!stored)
			t_.fail("unknown VTK data type '" + TextReader::printable(type) + "'");
		const bool float32 = type == "float";
		out.clear();
		if (binary_)
		{
			// the values start after the end of the current line
			t_.next_line();
			ByteReader b(data_, std::size_t(t_.position() - data_.data()), path_, true);
			const std::size_t size =
				float32 ? sizeof(float) : visit_value_type(*stored, []<typename T>() { return sizeof(T); });
			b.check_count(count, size, "values");
			out.reserve(count);
			auto read_all = [&]<typename T>() {
				for (uint64 i = 0; i < count; ++i)
				{
					const double v = double(b.read<T>());
					if (finite && !std::isfinite(v))
						b.fail("value is not finite: NaN and infinite values are rejected");
					out.push_back(v);
				}
			};
			if (float32)
				read_all.template operator()<float>();
			else
				visit_value_type(*stored, read_all);
			t_.set_position(data_.data() + b.position());
		}
		else
		{
			t_.check_count(count, 2, "values");
			out.reserve(count);
			const bool integer = is_integer_type(*stored);
			for (uint64 i = 0; i < count; ++i)
				out.push_back(integer ? double(t_.read_int("an integer")) : t_.read_double("a value"));
		}
	}

	// Reads an array of POINT_DATA or CELL_DATA; `names` holds the names read
	// before in the same kind of section, of every size (conflicts are checked
	// on all of them, though only arrays of 1 to 3 components are kept).
	void add_data(std::vector<Column>& target, std::vector<std::string>& names, bool of_points, const std::string& name,
				  uint32 dim, uint64 count, std::string_view type)
	{
		if (dim == 0)
			t_.fail("array '" + name + "' with 0 components");
		if (std::string why = data_name_conflict(names, name, of_points); !why.empty())
			t_.fail(why);
		names.push_back(name);
		std::vector<double> v;
		read_array(count * dim, type, v, false);
		// every array is kept: the load reports those no attribute holds
		target.push_back(Column{name, dim, std::move(v), vtk_legacy_value_type(type).value_or(ValueType::Float64)});
	}

	std::string_view data_;
	TextReader t_;
	const std::string& path_;
	bool binary_ = false;
	MeshData d_;
	std::vector<Column> cell_data_;
	std::vector<std::string> point_data_names_, cell_data_names_;
};

} // namespace

MeshData read_vtk(std::string_view data, const std::string& path)
{
	return VtkReader(data, path).read();
}

std::string write_vtk(const MeshData& d, bool binary)
{
	std::string s = "# vtk DataFile Version 3.0\nwritten by cgogn\n";
	s += binary ? "BINARY\n" : "ASCII\n";
	s += "DATASET UNSTRUCTURED_GRID\nPOINTS ";
	append_uint(s, d.nb_vertices());
	s += " double\n";
	auto put_double = [&](double v, bool last) {
		if (binary)
			append_raw_be(s, v);
		else
		{
			append_double(s, v);
			s += last ? '\n' : ' ';
		}
	};
	auto put_int = [&](uint32 v, bool last) {
		if (binary)
			append_raw_be(s, int32(v));
		else
		{
			append_uint(s, v);
			s += last ? '\n' : ' ';
		}
	};
	// an integer value of a column of type t (exact: see Column)
	auto put_integer = [&](double v, ValueType t) {
		if (!binary)
		{
			append_int(s, int64(v));
			s += '\n';
			return;
		}
		visit_value_type(t, [&]<typename T>() { append_raw_be(s, T(v)); });
	};
	for (std::size_t i = 0; i < d.positions.size(); ++i)
		put_double(d.positions[i], i % 3 == 2);
	if (binary)
		s += '\n';
	const std::size_t nb_segments = d.segments.size();
	// after the volume cells, the listed faces, then the segments
	const std::size_t nb_cells = d.nb_cells() + d.nb_faces() + nb_segments;
	// a polyhedron's entry is its face stream
	const std::vector<std::vector<uint32>> streams = polyhedron_streams(d);
	std::size_t size = d.nb_cells() + d.nb_faces() + d.face_vertices.size() + 3 * nb_segments;
	for (uint32 c = 0; c < d.nb_cells(); ++c)
		size += d.is_polyhedron(c) ? streams[c].size() : d.cell_sizes[c];
	s += "CELLS ";
	append_uint(s, nb_cells);
	s += ' ';
	append_uint(s, size);
	s += '\n';
	std::size_t k = 0;
	for (uint32 c = 0; c < d.nb_cells(); ++c)
	{
		const uint32 n = d.cell_sizes[c];
		const uint32* v = d.cell_vertices.data() + k;
		k += n;
		if (d.is_polyhedron(c))
		{
			put_int(uint32(streams[c].size()), false);
			for (std::size_t i = 0; i < streams[c].size(); ++i)
				put_int(streams[c][i], i + 1 == streams[c].size());
			continue;
		}
		put_int(n, false);
		for (uint32 i = 0; i < n; ++i)
			put_int(v[vtk_order(n, i)], i + 1 == n);
	}
	k = 0;
	for (uint32 n : d.face_sizes)
	{
		put_int(n, false);
		for (uint32 i = 0; i < n; ++i)
			put_int(d.face_vertices[k++], i + 1 == n);
	}
	for (const auto& [a, b] : d.segments)
	{
		put_int(2, false);
		put_int(a, false);
		put_int(b, true);
	}
	if (binary)
		s += '\n';
	s += "CELL_TYPES ";
	append_uint(s, nb_cells);
	s += '\n';
	std::vector<uint32> types;
	types.reserve(nb_cells);
	for (uint32 c = 0; c < d.nb_cells(); ++c)
		types.push_back(d.is_polyhedron(c) ? 42u : uint32(vtk_cell_type(d.cell_sizes[c])));
	for (uint32 n : d.face_sizes)
		types.push_back(vtk_face_type(n));
	types.insert(types.end(), nb_segments, 3u); // VTK_LINE
	for (uint32 t : types)
		put_int(t, true);
	if (binary)
		s += '\n';
	// every array in one FIELD block: VTK's reader keeps all the arrays of a
	// FIELD, but only the first of several SCALARS (or VECTORS)
	auto put_columns = [&](const std::vector<Column>& cols, const char* section, uint32 count) {
		std::vector<const Column*> written;
		for (const auto& c : cols)
			if (c.dim >= 1 && c.dim <= 3)
				written.push_back(&c);
		if (written.empty())
			return;
		s += section;
		s += ' ';
		append_uint(s, count);
		s += "\nFIELD FieldData ";
		append_uint(s, written.size());
		s += '\n';
		for (const Column* c : written)
		{
			const bool integer = c->dim == 1 && is_integer_type(c->type);
			s += c->name;
			s += ' ';
			append_uint(s, c->dim);
			s += ' ';
			append_uint(s, count);
			s += ' ';
			s += integer ? vtk_legacy_type_name(c->type) : "double";
			s += '\n';
			if (integer)
				for (double v : c->values)
					put_integer(v, c->type);
			else
				for (std::size_t i = 0; i < c->values.size(); ++i)
					put_double(c->values[i], i % c->dim == c->dim - 1);
			if (binary)
				s += '\n';
		}
	};
	put_columns(d.vertex_columns, "POINT_DATA", d.nb_vertices());
	put_columns(vtk_cell_data(d), "CELL_DATA", uint32(d.nb_cells() + d.nb_faces() + d.segments.size()));
	return s;
}

} // namespace cgogn::io::detail
