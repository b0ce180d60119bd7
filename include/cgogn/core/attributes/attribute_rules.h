// SPDX-License-Identifier: MIT
// Attributes that follow edits: each attribute has a rule (attribute_rule.h)
// that the operators apply to the cells they create. What each operator
// gives as parents is documented with the operator; in short:
// - a cell split in two: both parts have the cell as parent (weight 1);
// - a vertex inserted on an edge: the edge's two ends (1/2, 1/2);
// - a vertex inserted in a face (triangulate_face) or a volume
//   (split_tetra): the cell's vertices, with equal weights;
// - a corner (a dart of a 2-map, where per-corner data lives): the corners
//   it was cut from, or for a corner at a new vertex on an edge the corners
//   of the edge's two ends in the same face;
// - cells of a new dimension inside a parent (the edge cut_face adds, the
//   face cut_volume adds) have no parent of their orbit: default value;
// - merges (collapse, merge_incident_*, sew) keep the surviving cell's
//   line and value; modeling::decimate first interpolates the kept vertex
//   at the parameter of its new position along the edge.
#pragma once

#include <cgogn/core/attributes/attributes.h>

#include <array>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace cgogn
{

/// Sets the rule of attribute attr of m (see AttributeRule). add_attribute
/// gives each attribute its type's default_rule(). O(attributes with a rule).
template <typename MESH, typename A>
requires std::derived_from<A, AttributeBase>
void set_attribute_rule([[maybe_unused]] MESH& m, const std::shared_ptr<A>& attr, AttributeRule rule)
{
	assert(attr && attr->container() != nullptr && "attribute removed from its map");
	assert(rule != AttributeRule::Callback && "give the callback: set_attribute_rule(m, attr, f)");
	attr->container()->set_rule(*attr, rule);
}

/// Gives attr the rule Callback with function f(value, parents, weights),
/// which sets `value` (the new cell's) from its parents' values and weights
/// (see AttributeArray::RuleCallback). O(attributes with a rule).
template <typename MESH, typename A>
requires std::derived_from<A, AttributeBase>
void set_attribute_rule([[maybe_unused]] MESH& m, const std::shared_ptr<A>& attr,
						typename AttributeArray<typename A::value_type>::RuleCallback f)
{
	assert(attr && attr->container() != nullptr && "attribute removed from its map");
	attr->set_rule_callback(std::move(f));
	attr->container()->set_rule(*attr, AttributeRule::Callback);
}

/// The rule of attr. O(1).
inline AttributeRule attribute_rule(const AttributeBase& attr)
{
	return attr.rule();
}

/// Sets the rule of an attribute to None for the lifetime of this object,
/// then gives its rule back: what an algorithm does with the positions it
/// computes itself, so that operators do not interpolate values about to be
/// overwritten.
class SuspendedRule
{
public:
	/// Sets the rule of attr to None (nothing when it has none or was
	/// removed from its map). O(attributes with a rule).
	explicit SuspendedRule(AttributeBase& attr) : attr_(attr), rule_(attr.rule())
	{
		if (rule_ != AttributeRule::None && attr_.container() != nullptr)
			attr_.container()->set_rule(attr_, AttributeRule::None);
	}
	/// Gives the attribute its rule back. O(attributes with a rule).
	~SuspendedRule()
	{
		if (rule_ != AttributeRule::None && attr_.container() != nullptr)
			attr_.container()->set_rule(attr_, rule_);
	}
	SuspendedRule(const SuspendedRule&) = delete;
	SuspendedRule& operator=(const SuspendedRule&) = delete;

private:
	AttributeBase& attr_;
	AttributeRule rule_;
};

/// Records where cells of type CELL come from: a uint32 attribute `name`
/// holding, for every existing cell, its own line (index_of), and for every
/// cell made later by an operator the value of its parent (rule Copy). Cells
/// with no parent of their orbit (a face filling a hole) hold INVALID_INDEX.
/// Returns nullptr when the name is taken. O(number of cells).
template <typename CELL, typename MESH>
std::shared_ptr<CellAttribute<uint32, CELL::ORBIT>> record_origins(MESH& m, const std::string& name = "origin")
{
	auto& map = map_of(m);
	if (detail::is_reserved_name(name) || container_of<CELL::ORBIT>(map).find(name) != nullptr)
		return nullptr;
	if (!is_indexed<CELL>(map))
		index_cells<CELL>(map);
	auto& container = container_of<CELL::ORBIT>(map);
	auto origin = container.template add_attribute<uint32, CellAttribute<uint32, CELL::ORBIT>>(name, INVALID_INDEX);
	for (uint32 i = container.first_index(); i < container.end_index(); i = container.next_index(i))
		(*origin)[i] = i;
	container.set_rule(*origin, AttributeRule::Copy);
	return origin;
}

namespace detail
{

/// Whether some attribute of the map has a rule: operators test it once
/// before applying rules. O(1).
inline bool has_rules(const CMapBase& m)
{
	return *state_of(m).nb_ruled_attributes != 0;
}

/// Applies the rules of the attributes of orbit O to the cell of dart
/// `child` from the cells of `parents` with weights `w` (summing to 1; an
/// empty `w` gives every parent the same weight). Parents without a line
/// (boundary cells) are left out and the others' weights scaled back to a
/// sum of 1. One test when no attribute of O has a rule; else O(parents +
/// rules x parents), allocating only beyond 8 parents.
template <Orbit O>
void inherit(CMapBase& m, Dart child, std::span<const Dart> parents, std::span<const double> w)
{
	AttributeContainer& c = container_of<O>(m);
	if (!c.has_rules())
		return;
	const uint32 dst = index_of(m, Cell<O>(child));
	if (dst == INVALID_INDEX)
		return;
	constexpr std::size_t SMALL = 8;
	std::array<uint32, SMALL> small_lines;
	std::array<double, SMALL> small_w;
	std::vector<uint32> big_lines;
	std::vector<double> big_w;
	uint32* lines = small_lines.data();
	double* weights = small_w.data();
	if (parents.size() > SMALL)
	{
		big_lines.resize(parents.size());
		big_w.resize(parents.size());
		lines = big_lines.data();
		weights = big_w.data();
	}
	std::size_t n = 0;
	double sum = 0.0;
	for (std::size_t k = 0; k < parents.size(); ++k)
	{
		const uint32 line = index_of(m, Cell<O>(parents[k]));
		if (line == INVALID_INDEX)
			continue;
		lines[n] = line;
		weights[n] = w.empty() ? 1.0 : w[k];
		sum += weights[n];
		++n;
	}
	if (n == 0)
		return;
	if (sum != 1.0 && sum > 0.0)
		for (std::size_t k = 0; k < n; ++k)
			weights[k] /= sum;
	c.apply_rules(dst, std::span<const uint32>(lines, n), std::span<const double>(weights, n));
}

/// Line dst of orbit O, given to a part of a cell that came apart (a vertex
/// cut in two by an unsew, a component split), gets the values of line src,
/// the line the cell had (kept by another part). O(rules) when some
/// attribute of O has a rule.
template <Orbit O>
void inherit_line(CMapBase& m, uint32 dst, uint32 src)
{
	AttributeContainer& c = container_of<O>(m);
	if (!c.has_rules() || dst == INVALID_INDEX || src == INVALID_INDEX || dst == src)
		return;
	const double one = 1.0;
	c.apply_rules(dst, std::span<const uint32>(&src, 1), std::span<const double>(&one, 1));
}

/// The same for one parent (a part of a split cell): its value, by any rule.
template <Orbit O>
void inherit(CMapBase& m, Dart child, Dart parent)
{
	if (container_of<O>(m).has_rules())
		inherit_line<O>(m, index_of(m, Cell<O>(child)), index_of(m, Cell<O>(parent)));
}

/// The same for two parents of equal weight (a vertex in the middle of an
/// edge, a corner there).
template <Orbit O>
void inherit_midpoint(CMapBase& m, Dart child, Dart a, Dart b)
{
	if (!container_of<O>(m).has_rules())
		return;
	const std::array<Dart, 2> parents{a, b};
	const std::array<double, 2> w{0.5, 0.5};
	inherit<O>(m, child, parents, w);
}

/// The same with equal weights on every parent (the centre of a face or a
/// volume).
template <Orbit O>
void inherit_mean(CMapBase& m, Dart child, std::span<const Dart> parents)
{
	inherit<O>(m, child, parents, {});
}

/// The values of the attributes of a container that have a rule, saved
/// before an algorithm rebuilds the map (the volume subdivisions clear it
/// and build the refined cells): apply() then gives a line of the rebuilt
/// map its rules' values from saved lines. O(lines x attributes with a
/// rule) to save.
class RuleSnapshot
{
public:
	explicit RuleSnapshot(AttributeContainer& c) : saved_("__saved")
	{
		saved_.set_orbit(c.orbit());
		if (!c.has_rules())
			return;
		const uint32 end = c.end_index();
		scratch_ = saved_.new_lines_at_end(end + 1) + end;
		for (const auto& a : c.attributes())
			if (a->rule() != AttributeRule::None)
			{
				std::shared_ptr<AttributeBase> copy = a->clone_empty(saved_);
				for (uint32 i = c.first_index(); i < end; i = c.next_index(i))
					copy->copy_line_from(i, *a, i);
				saved_attributes_.push_back({a.get(), std::move(copy)});
			}
	}
	/// Whether some attribute has a rule (else apply does nothing).
	bool empty() const
	{
		return saved_attributes_.empty();
	}
	/// Sets line `line` of every attribute with a rule from the saved lines
	/// `parents` with weights `w`. O(attributes with a rule x parents).
	void apply(uint32 line, std::span<const uint32> parents, std::span<const double> w)
	{
		for (auto& [attribute, copy] : saved_attributes_)
		{
			copy->reset_line(scratch_);
			copy->apply_rule(scratch_, parents, w);
			attribute->copy_line_from(line, *copy, scratch_);
		}
	}

private:
	AttributeContainer saved_;
	uint32 scratch_ = 0;
	std::vector<std::pair<AttributeBase*, std::shared_ptr<AttributeBase>>> saved_attributes_;
};

} // namespace detail

/// Applies the rules of the attributes of CELL's orbit to cell `dst` from
/// the N cells `parents` with weights `w` (summing to 1; dst may be one of
/// the parents): for algorithms that know better parents than an operator,
/// such as the kept end of a collapsed edge placed between its two ends.
/// Allocates nothing. O(N + rules x N).
template <typename CELL, typename MESH, std::size_t N>
void apply_attribute_rules(MESH& m, CELL dst, const CELL (&parents)[N], const double (&w)[N])
{
	if (!container_of<CELL::ORBIT>(map_of(m)).has_rules())
		return;
	std::array<Dart, N> darts;
	for (std::size_t k = 0; k < N; ++k)
		darts[k] = parents[k].dart;
	detail::inherit<CELL::ORBIT>(map_of(m), dst.dart, darts, std::span<const double>(w, N));
}

} // namespace cgogn
