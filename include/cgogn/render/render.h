// SPDX-License-Identifier: MIT
// Software rendering of a surface, or of the boundary of a volume mesh, into
// an RGB picture: no GPU and no display needed. The library prints nothing:
// every failure is a RenderError.
//
// Camera: orthographic, looking at the centre of the axis-aligned bounding
// box of the rendered vertices, scaled so that the projection of that box
// fills 90% of the drawing area's width or height (whichever is reached
// first), centred in it. The drawing area is the whole image, minus a strip
// on the right for the legend when a scalar is shown (see legend_width()).
// Base views (camera frame: right, up, and `back` pointing at the viewer):
//   z:   looks down -z, +y up, +x to the right
//   x:   looks down -x, +z up, +y to the right
//   y:   looks down -y, +z up, -x to the right
//   iso: the z view turned by azimuth 45 and elevation 35.26 degrees, i.e.
//        looking down -(1, 1, 1) with +y up
// The azimuth then turns the camera about the view's up axis (positive: from
// its `back` towards its `right`), and the elevation raises it towards the up
// axis, both in degrees, on top of the base view. The light is a headlight
// (coming from the camera) and lights both sides of every face.
#pragma once

#include <cgogn/core/map/cmap3.h>
#include <cgogn/core/map/graph.h>
#include <cgogn/core/map/incidence_graph.h>
#include <cgogn/geometry/types/vector_traits.h>

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace cgogn::render
{

/// Every failure of the renderer: empty mesh, non-finite positions, unknown
/// attribute, bad option, unwritable file.
class RenderError : public std::runtime_error
{
public:
	using std::runtime_error::runtime_error;
};

/// A colour, 8 bits per channel.
struct Rgb
{
	/// \var r
	/// Red, 0..255.
	/// \var g
	/// Green, 0..255.
	/// \var b
	/// Blue, 0..255.
	uint8_t r = 0, g = 0, b = 0;
	/// Same three channels.
	friend bool operator==(Rgb, Rgb) = default;
};

/// The base view of the camera, before RenderOptions::azimuth and elevation.
enum class View
{
	X,  ///< looks down -x, +z up, +y to the right
	Y,  ///< looks down -y, +z up, -x to the right
	Z,  ///< looks down -z, +y up, +x to the right
	Iso ///< the Z view turned by azimuth 45 and elevation 35.26 degrees: looks down -(1, 1, 1), +y up
};

enum class Shading
{
	Flat,  ///< one normal per face
	Smooth ///< vertex normals (area-weighted face normals) interpolated per pixel
};

/// What sets the colour of the surface. Scalars are mapped through viridis
/// over a range: by default the robust range of the rendered values (their
/// 2nd to 98th percentile, see scalar_range()), or the one given by
/// RenderOptions::range_min / range_max; values beyond it get the colour of
/// its nearest end.
enum class ColorSource
{
	Uniform,           ///< RenderOptions::surface_color
	MeanCurvature,     ///< per vertex, geometry::mean_curvature (surfaces only)
	GaussianCurvature, ///< per vertex, geometry::gaussian_curvature (surfaces only)
	Area,              ///< per face, geometry::face_area
	Quality,           ///< per face, triangle_quality() (polygons: their worst fan triangle)
	Attribute          ///< RenderOptions::attribute: a double or float vertex, face or volume attribute
};

/// How render_surface and render_volume_boundary draw a mesh. The camera is
/// orthographic, looks at the centre of the bounding box of the rendered
/// vertices and is scaled so that the box fills 90% of the drawing area (the
/// image minus the legend strip) in width or height.
struct RenderOptions
{
	/// Width of the image in pixels, 1..32768; width x height x supersampling^2
	/// is at most 2^26 (RenderError otherwise).
	uint32_t width = 800, height = 600; ///< Height of the image in pixels, 1..32768.
	View view = View::Iso;              ///< The base view of the camera.
	/// Degrees the camera turns about the view's up axis, from its back towards
	/// its right, on top of `view`.
	double azimuth = 0.0, elevation = 0.0; ///< Degrees the camera rises towards the up axis, on top of `view`.
	Shading shading = Shading::Smooth;     ///< Flat or smooth shading.
	/// Each pixel is the mean of ssaa x ssaa samples (1: no anti-aliasing).
	uint32_t supersampling = 2;
	/// Wireframe of the mesh edges, depth-tested with a small bias.
	bool edges = false;
	/// Boundary edges in red and split (non-manifold) vertices as orange dots,
	/// depth-tested with the bias of the edges: the visible ones in full
	/// colour, the hidden ones blended at 25% over what hides them, so that
	/// they show without covering the object.
	bool show_defects = false;
	ColorSource color = ColorSource::Uniform; ///< What sets the colour of the surface.
	std::string attribute;                    ///< the attribute's name, for ColorSource::Attribute
	/// The low end of the colour range of a scalar; unset: the 2nd percentile
	/// of the rendered values. Set both ends or neither, with range_min <
	/// range_max (RenderError otherwise).
	std::optional<double> range_min, range_max; ///< The high end (unset: the 98th percentile).
	/// Colour bar on the right when a scalar is shown, with the ends of the
	/// range used; an end that clamps some values gets a triangle beyond it.
	bool legend = true;
	/// false: colours as they are, without the light (0.2 + 0.8 |n.l| otherwise).
	bool lighting = true;
	Rgb background{255, 255, 255};    ///< Colour of the pixels no face covers (the legend's text contrasts with it).
	Rgb surface_color{190, 198, 214}; ///< Colour of the faces for ColorSource::Uniform.
	Rgb edge_color{35, 35, 40};       ///< Colour of the wireframe (see `edges`).
};

/// An 8-bit RGB picture, rows from the top, 3 bytes per pixel.
struct Image
{
	/// Width in pixels.
	uint32_t width = 0, height = 0; ///< Height in pixels.
	std::vector<uint8_t> rgb;       ///< width x height pixels, row by row from the top: r, g, b of each.

	/// The pixel of column x (from the left) and row y (from the top);
	/// x < width and y < height (not checked). O(1).
	Rgb at(uint32_t x, uint32_t y) const
	{
		const std::size_t i = (std::size_t(y) * width + x) * 3;
		return {rgb[i], rgb[i + 1], rgb[i + 2]};
	}
};

/// Renders the non-boundary faces of m (polygons fanned into triangles) with
/// positions pos. O(number of darts + number of samples), single-threaded and
/// deterministic: the same map, positions and options give the same bytes.
/// Memory: about 12 bytes per sample (width x height x supersampling^2) plus
/// about 100 bytes per triangle.
/// Throws RenderError when the map has no face, a rendered vertex has a
/// non-finite position, an option is out of range (empty size, supersampling
/// outside 1..8, more than 2^26 samples), the colour source needs what the
/// mesh does not have (the list of the usable attributes is in the message).
/// Precondition: pos is a vertex attribute of m.
Image render_surface(const CMap2& m, const AttributeArray<Vec3>& pos, const RenderOptions& options);

/// Renders the boundary of a volume mesh: the faces of the volumes whose
/// phi3 neighbour is a boundary volume, seen from outside. Same costs and
/// errors as render_surface; a map with no boundary face is an error, and the
/// curvature colour sources are not available (they are defined on surfaces).
Image render_volume_boundary(const CMap3& m, const AttributeArray<Vec3>& pos, const RenderOptions& options);

/// Renders the faces of an incidence graph (polygons fanned into
/// triangles), and its edges without face as lines in the edge colour: a
/// non-manifold surface drawn as it is, flat-shaded (the faces around a
/// non-manifold vertex have no common normal). With show_defects, the edges that do
/// not have exactly two faces (borders, fins, wires) are drawn in red and
/// the vertices that are not manifold as orange dots. Colour sources: as for
/// render_surface but the curvatures (not defined where the surface
/// branches); `Attribute` takes a double or float vertex or face attribute.
/// Throws RenderError when the complex has no face and no edge, and as
/// render_surface. O(size of ig + number of samples).
Image render_surface(const IncidenceGraph& ig, const AttributeArray<Vec3>& pos, const RenderOptions& options);

/// How render_graph draws a graph.
struct GraphDrawing
{
	/// true: each edge a tube (an 8-sided prism, shaded) and each vertex a
	/// ball (an octahedron), so that the picture shows depth; false: each
	/// edge a line one pixel wide in RenderOptions::edge_color.
	bool tubes = true;
	/// The tubes' radius; 0: the vertex attribute "radius" when the graph has
	/// one (each tube then tapers between its ends' radii), otherwise 0.5% of
	/// the diagonal of the bounding box.
	double radius = 0.0;
};

/// Renders a graph (skeleton, curve network) as tubes or lines. Colour
/// sources: Uniform, or Attribute (a double or float vertex attribute,
/// interpolated along the tubes); the others throw RenderError. Throws
/// RenderError when the graph has no vertex, a position is not finite, or
/// an option is out of range. O(size of g + number of samples).
Image render_graph(const Graph& g, const AttributeArray<Vec3>& pos, const RenderOptions& options,
				   const GraphDrawing& drawing = {});

/// What `viewer_html` puts in the page and how the page opens.
struct ViewerOptions
{
	std::string title; ///< shown on the page; empty: "cgogn view"
	/// The colouring selected when the page opens (ColorSource::Attribute:
	/// the attribute named `attribute`).
	ColorSource color = ColorSource::Uniform;
	/// The attribute's name, for ColorSource::Attribute: a double or float
	/// vertex, face or volume attribute (RenderError when there is none of
	/// that name).
	std::string attribute;
	/// Every colour quantity the mesh has (true), or only `color` (smaller
	/// page: each quantity costs 1.33 bytes per vertex or per triangle).
	bool all_quantities = true;
	bool edges = false;        ///< edges shown when the page opens
	bool show_defects = false; ///< boundary edges and split vertices shown when the page opens
};

/// A self-contained HTML page (three.js and the page's script inline, no
/// network access) that draws a surface in the browser with WebGL 2:
/// rotate, zoom and pan, toggles for edges, boundary edges and split
/// vertices, a choice of colouring with a legend. Positions are embedded as
/// base64 Float32, triangles (polygons fanned) as base64 Uint32, one flag
/// byte per triangle, and each colour quantity as base64 Uint8: its values
/// computed here as render_surface computes them, normalized over
/// scalar_range() to 0..254 (255: no value; the page maps them to the 256
/// viridis colours). O(number of darts + number of triangles x number of
/// quantities); the page is about 12 bytes per vertex plus 13 bytes per
/// triangle, times 4/3 (base64), plus 1.33 bytes per vertex or triangle and
/// quantity, plus 0.5 MB of script: 30 MB for 1M triangles with the four
/// quantities of a surface.
/// Throws RenderError as render_surface (empty mesh, non-finite position,
/// unknown attribute). Precondition: pos is a vertex attribute of m.
std::string viewer_html(const CMap2& m, const AttributeArray<Vec3>& pos, const ViewerOptions& options = {});

/// The same for a volume mesh: the page draws its boundary faces (the faces
/// whose phi3 neighbour is a boundary volume) and offers a clipping plane,
/// normal to x, y or z, that shows the cells it cuts: the volume cells
/// entirely beyond the plane are hidden, the cells the plane crosses are
/// drawn whole (all their faces), and the cells entirely on the kept side
/// show their boundary faces. Every face of every cell is embedded (an inner
/// face twice, once per cell), grouped by cell. Colour quantities: area,
/// quality and the double/float vertex, face and volume attributes (no
/// curvature). Throws RenderError also when the map has no boundary face.
std::string viewer_html(const CMap3& m, const AttributeArray<Vec3>& pos, const ViewerOptions& options = {});

/// viewer_html written to path, through a temporary file next to it that is
/// renamed: a failure never leaves a partial file. Throws RenderError
/// naming path when it cannot be written; nothing is written when the page
/// cannot be made.
void write_viewer_html(const CMap2& m, const AttributeArray<Vec3>& pos, const std::string& path,
					   const ViewerOptions& options = {});
void write_viewer_html(const CMap3& m, const AttributeArray<Vec3>& pos, const std::string& path,
					   const ViewerOptions& options = {});

/// Writes bytes (a page of viewer_html) to path through a temporary file
/// next to it that is renamed. Throws RenderError naming path.
void write_file(const std::string& bytes, const std::string& path);

/// Writes img as an 8-bit RGB PNG (no time stamp: same image, same bytes).
/// Writes a temporary file next to path and renames it, so that a failure
/// never leaves a partial file at path. O(number of pixels). Throws
/// RenderError naming path when it cannot be written or img is empty.
void write_png(const Image& img, const std::string& path);

/// The range a scalar field is coloured over: values in [lo, hi] map
/// linearly to [0, 1], values beyond are clamped; `below` / `above` tell
/// whether some values lie beyond each end.
struct ScalarRange
{
	/// The value mapped to 0.
	double lo = 0.0, hi = 0.0; ///< The value mapped to 1.
	/// Whether some values are below lo.
	bool below = false, above = false; ///< Whether some values are above hi.
	/// v in [0, 1] (0.5 when lo == hi); NaN for a non-finite v.
	double normalized(double v) const;
};

/// The colour range of values (non-finite ones ignored): [min, max] when
/// given, otherwise the 2nd and 98th percentiles (linear between the sorted
/// values), so that a few outliers do not squeeze the other values into one
/// colour. No finite value: {0, 0}. O(n) (selections, not a sort). Throws
/// RenderError when only one end is given, when min >= max or an end is not
/// finite.
ScalarRange scalar_range(const std::vector<double>& values, std::optional<double> min = {},
						 std::optional<double> max = {});

/// The viridis colour map at t in [0, 1] (clamped; NaN gives t = 0), linear
/// between the 256 entries of matplotlib's table. O(1).
Rgb viridis(double t);

/// "#rrggbb", "rrggbb" or "r,g,b" (0..255) as a colour; throws RenderError.
Rgb parse_color(const std::string& text);

/// Quality of a triangle: 4 sqrt(3) area / (sum of the squared edge
/// lengths), 1 for an equilateral triangle, 0 for a degenerate one. O(1).
double triangle_quality(const Vec3& a, const Vec3& b, const Vec3& c);

/// Width in pixels of the legend strip on the right of an image of this size
/// (when a scalar is shown with RenderOptions::legend): 48 * max(1, height /
/// 200), at most half the width. O(1).
uint32_t legend_width(uint32_t width, uint32_t height);

} // namespace cgogn::render
