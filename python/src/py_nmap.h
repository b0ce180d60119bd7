// SPDX-License-Identifier: MIT
// What the bindings of the maps of any dimension (CMapN<D>, GMapN<D>, D = 1
// ... MAX_PY_DIMENSION) share: the interface every map class offers to the
// code written once for all of them (attributes, counts, incidence rows,
// files), and the functions that make the instances of the classes of each
// model, defined in their own translation units.
#pragma once

#include <cgogn/core/map/nmap.h>
#include <cgogn/core/properties/integrity.h>

#include "py_arrays.h"

#include <memory>
#include <string>
#include <vector>

namespace cgogn::python
{

/// The largest dimension of the map classes Python has (CMapN1 ... CMapN4,
/// GMapN1 ... GMapN4).
inline constexpr uint32 MAX_PY_DIMENSION = 4;

/// The rows of an incidence relation, in the traversal order of its source
/// cells: the id of each source cell (`rows`), and the ids of the target
/// cells of row r at indices[offsets[r] .. offsets[r + 1]).
struct IncidenceRows
{
	std::vector<uint32> rows;
	std::vector<uint32> offsets{0};
	std::vector<uint32> indices;
};

/// A map of any dimension as Python sees it (the base class `NMap`): what
/// depends on the map's type behind virtual functions, implemented once per
/// map type by PyNMap<MAP> (py_nmap_class.h), so that the code written for
/// every map (attributes, arrays, files) is compiled once.
struct NMap
{
	/// Weak references to the NumPy arrays that alias the map's attributes.
	std::vector<py::object> views;

	NMap() = default;
	NMap(const NMap&) = delete;
	NMap& operator=(const NMap&) = delete;
	virtual ~NMap() = default;

	virtual uint32 dimension() const = 0;
	virtual bool is_gmap() const = 0;
	virtual CMapBase& map() = 0;
	virtual const CMapBase& map() const = 0;
	/// Indexes the k-cells when they are not (O(darts), once); k <= dimension().
	virtual void index(uint32 k) = 0;
	/// Number of k-cells, boundary cells excluded.
	virtual uint32 nb_cells(uint32 k) const = 0;
	/// The ids of the k-cells (boundary cells excluded), in traversal order;
	/// indexes them.
	virtual std::vector<uint32> cell_ids(uint32 k) = 0;
	/// For each i-cell, the j-cells incident to it (foreach_incident_cell:
	/// each once, boundary cells excluded); indexes both dimensions.
	virtual IncidenceRows incidence(uint32 i, uint32 j) = 0;
	virtual uint32 nb_connected_components() const = 0;
	virtual IntegrityReport check_integrity() const = 0;
	/// Reads a .nmap file into this map, which has no dart (io::load_nmap).
	virtual void load_nmap(const std::string& path) = 0;
	/// Writes the .nmap file; returns the names of the attributes not written.
	virtual std::vector<std::string> save_nmap(const std::string& path) const = 0;
	/// The bytes of the map's .cgmap file (io::save_map_to_bytes); the names
	/// of the attributes left out go to `skipped` when given.
	virtual std::string map_bytes(std::vector<std::string>* skipped = nullptr) const = 0;
	/// Writes the cells of the given dimensions as a VTK XML unstructured grid.
	virtual void save_vtu(const std::string& path, const std::vector<uint32>& dimensions) const = 0;
	/// The boundary as a map of dimension D - 1 (D >= 2), vertex attributes carried.
	virtual py::object boundary() const = 0;
	/// The map of the other model: to_gmap of a CMapN, to_cmap of a GMapN.
	virtual py::object convert() const = 0;
};

/// An empty CMapN<D> (bind_cmapn.cpp) or GMapN<D> (bind_gmapn.cpp), 1 <= D <=
/// MAX_PY_DIMENSION, as an instance of its Python class.
py::object new_cmapn(uint32 D);
py::object new_gmapn(uint32 D);

/// A map moved into an instance of its Python class. Instantiated for D = 1
/// ... MAX_PY_DIMENSION in bind_cmapn.cpp and bind_gmapn.cpp.
template <uint32 D>
py::object wrap_nmap(CMapN<D>&& m);
template <uint32 D>
py::object wrap_nmap(GMapN<D>&& m);

/// The classes CMapN1 ... CMapN4 and GMapN1 ... GMapN4, once NMap is bound.
void bind_cmapn(py::module_& m);
void bind_gmapn(py::module_& m);
/// NMap and the classes of both models (bind_nmaps.cpp).
void bind_nmaps(py::module_& m);

/// Whether path ends with .nmap (any case).
bool has_nmap_extension(const std::string& path);
/// The map of a .nmap file, as an instance of the class of its model and
/// dimension; with `gmap`, the GMapN of a file holding a CMapN. Raises
/// io::Error for a bad file or a dimension above MAX_PY_DIMENSION.
py::object load_nmap_file(const std::string& path, bool gmap);

} // namespace cgogn::python
