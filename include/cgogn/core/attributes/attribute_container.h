// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/attributes/attribute.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <mutex>
#include <span>
#include <type_traits>
#include <utility>

namespace cgogn
{

/// A set of attributes that all have the same lines. One attribute, the key
/// (an AttributeArray<uint32>), tells which lines are live: a line is free when its
/// key is INVALID_INDEX. For a map's dart container the key is phi1; for a cell
/// container it is the representative dart of each cell. Free lines are kept
/// in a list and reused first. Mark attributes (a bit per line) are reserved
/// from a pool: reservation is thread-safe and lock-free for the first 64.
class AttributeContainer
{
public:
	/// `max_contiguous_lines` caps the lines each attribute and mark keeps in
	/// its reserved range (see LineStorage); the lines beyond go to blocks.
	/// Only tests lower it, to exercise the blocks with small containers.
	explicit AttributeContainer(const std::string& key_name, uint64 max_contiguous_lines = ~uint64(0))
		: max_contiguous_lines_(max_contiguous_lines)
	{
		key_ = add_attribute<uint32>(key_name, INVALID_INDEX).get();
	}
	~AttributeContainer()
	{
		for (auto& a : attributes_)
		{
			a->container_ = nullptr;
			a->cell_index_ = nullptr;
		}
	}
	AttributeContainer(const AttributeContainer&) = delete;
	AttributeContainer& operator=(const AttributeContainer&) = delete;

	/// Adds an attribute whose lines all hold `default_value`; nullptr when one
	/// with this name exists already. A is the attribute's class (a
	/// CellAttribute<T, O> for add_attribute<T, CELL>). O(attributes + capacity()).
	template <typename T, typename A = AttributeArray<T>>
	std::shared_ptr<A> add_attribute(const std::string& name, T default_value = T())
	{
		static_assert(std::is_base_of_v<AttributeArray<T>, A>);
		return std::static_pointer_cast<A>(add_attribute_made_by<T>(&A::make, name, std::move(default_value)));
	}

	/// The factory of an attribute class of values of type T (its static
	/// `make`, see AttributeArray::make).
	template <typename T>
	using Factory = std::shared_ptr<AttributeBase> (*)(AttributeContainer*, std::string, T, uint64);

	/// add_attribute for the class whose factory is `make`: for callers that
	/// choose the class at run time (the orbit of a clone, or of an attribute
	/// read from a file) with one call instead of a call per class.
	/// O(attributes + capacity()).
	template <typename T>
	std::shared_ptr<AttributeBase> add_attribute_made_by(Factory<T> make, const std::string& name, T default_value)
	{
		if (find(name) != nullptr)
			return nullptr;
		std::shared_ptr<AttributeBase> a =
			make(this, name, std::move(default_value),
				 std::min(max_contiguous_lines_, LineStorage<T, CHUNK_SHIFT>::default_contiguous()));
		adopt(a);
		return a;
	}

	/// The attribute of this name and type; nullptr when absent or of another type.
	template <typename T>
	std::shared_ptr<AttributeArray<T>> get_attribute(const std::string& name) const
	{
		auto a = find(name);
		if (a == nullptr || a->type() != typeid(T))
			return nullptr;
		return std::static_pointer_cast<AttributeArray<T>>(a);
	}

	/// The attribute of this name, whatever its type; nullptr when absent.
	/// O(number of attributes).
	std::shared_ptr<AttributeBase> find(const std::string& name) const;

	/// Removes the attribute (not the key); returns false when it is not here.
	bool remove_attribute(const AttributeBase* attr)
	{
		if (attr == key_)
			return false;
		auto it = std::find_if(attributes_.begin(), attributes_.end(), [&](const auto& a) { return a.get() == attr; });
		if (it == attributes_.end())
			return false;
		(*it)->container_ = nullptr;
		(*it)->cell_index_ = nullptr;
		if (std::erase(ruled_, it->get()) > 0 && map_rule_count_ != nullptr)
			--*map_rule_count_;
		attributes_.erase(it);
		return true;
	}

	/// Gives attribute a (one of this container's) rule r; Callback needs
	/// the attribute's callback set first (asserted by apply_rule's caller).
	/// O(attributes with a rule).
	void set_rule(AttributeBase& a, AttributeRule r)
	{
		assert(a.container() == this);
		a.rule_ = r;
		const bool was_ruled = std::erase(ruled_, &a) > 0;
		if (r != AttributeRule::None)
			ruled_.push_back(&a);
		if (map_rule_count_ != nullptr && was_ruled != (r != AttributeRule::None))
			*map_rule_count_ = was_ruled ? *map_rule_count_ - 1 : *map_rule_count_ + 1;
	}
	/// Gives attribute a, of type T, its type's default rule (default_rule<T>():
	/// what add_attribute and the map file reader give new attributes).
	template <typename T>
	void set_default_rule(AttributeBase& a)
	{
		if constexpr (default_rule<T>() != AttributeRule::None)
			set_rule(a, default_rule<T>());
	}
	/// Makes the container count its attributes with a rule in *count too
	/// (the map's total, see MapState::nb_ruled_attributes).
	void count_rules_in(uint32* count)
	{
		map_rule_count_ = count;
	}
	/// Whether some attribute has a rule: operators apply rules only then,
	/// so that maps without rules pay one test per created cell. O(1).
	bool has_rules() const
	{
		return !ruled_.empty();
	}
	/// Applies the rule of every attribute that has one to line dst, from
	/// the parent lines src with weights w (see AttributeBase::apply_rule).
	/// O(attributes with a rule x parents).
	void apply_rules(uint32 dst, std::span<const uint32> src, std::span<const double> w)
	{
		for (AttributeBase* a : ruled_)
			a->apply_rule(dst, src, w);
	}

	/// Every attribute of the container, the key included, in the order they
	/// were added.
	const std::vector<std::shared_ptr<AttributeBase>>& attributes() const
	{
		return attributes_;
	}

	/// The key: INVALID_INDEX on free lines (see the class). Writing it does
	/// not update the free list; new_line and release_line do.
	AttributeArray<uint32>& key()
	{
		return *key_;
	}

	/// The orbit whose cells own the lines of this container (DART for the
	/// dart container); set by the map.
	Orbit orbit() const
	{
		return orbit_;
	}
	/// Sets the orbit (see orbit()); the map calls it when it creates the container.
	void set_orbit(Orbit o)
	{
		orbit_ = o;
	}
	/// The dart attribute that holds each dart's line in this container
	/// (nullptr while the orbit is not indexed); set by the map when it
	/// indexes the orbit. `attr[cell]` reads it.
	const AttributeArray<uint32>* cell_index() const
	{
		return cell_index_;
	}
	/// Sets the cell index (see cell_index()) and hands it to every attribute.
	/// O(number of attributes).
	void set_cell_index(const AttributeArray<uint32>* index)
	{
		cell_index_ = index;
		for (auto& a : attributes_)
			a->cell_index_ = index;
	}
	/// The key, read-only: INVALID_INDEX on free lines.
	const AttributeArray<uint32>& key() const
	{
		return *key_;
	}

	/// A new line (a freed one first) with every attribute at its default
	/// value but the key, set to `key_value`. O(number of attributes).
	uint32 new_line(uint32 key_value)
	{
		uint32 i;
		if (!free_lines_.empty())
		{
			i = free_lines_.back();
			free_lines_.pop_back();
			for (auto& a : attributes_)
				a->reset_line(i);
		}
		else
		{
			if (size_ == nb_chunks_ * CHUNK_SIZE)
				set_nb_chunks(nb_chunks_ + 1);
			i = size_++;
		}
		(*key_)[i] = key_value;
		return i;
	}

	/// Two new lines 2k and 2k + 1 (a freed aligned pair first), each keyed by
	/// its own index; returns 2k. The generalized maps allocate their darts
	/// so, beta0 being the other line of the pair. Precondition: every line so
	/// far was allocated in aligned pairs (end_index() is even). O(number of
	/// attributes).
	uint32 new_line_pair()
	{
		assert(size_ % 2 == 0);
		uint32 i;
		const std::size_t nf = free_lines_.size();
		if (nf >= 2 && (free_lines_[nf - 1] ^ 1u) == free_lines_[nf - 2])
		{
			i = std::min(free_lines_[nf - 1], free_lines_[nf - 2]);
			free_lines_.resize(nf - 2);
			for (auto& a : attributes_)
			{
				a->reset_line(i);
				a->reset_line(i + 1);
			}
		}
		else
		{
			i = new_lines_at_end(2);
		}
		(*key_)[i] = i;
		(*key_)[i + 1] = i + 1;
		return i;
	}

	/// `n` new consecutive lines at the end of the container (free lines are
	/// left for later); returns the first. Their keys are INVALID_INDEX: the
	/// caller sets them (or releases the lines it does not use).
	uint32 new_lines_at_end(uint32 n)
	{
		uint32 first = size_;
		uint64 needed = (uint64(size_) + n + CHUNK_SIZE - 1) / CHUNK_SIZE;
		if (needed > nb_chunks_)
			set_nb_chunks(uint32(needed));
		size_ += n;
		return first;
	}

	/// Gives an empty container the lines a saved one had: end_index()
	/// becomes `end` (every attribute holds it, at its default value) and
	/// the free list becomes `free_lines`, in that order (new_line reuses
	/// the last one first). The caller then writes the values, keys included,
	/// so that the free lines, and only they, have INVALID_INDEX keys.
	/// Precondition: end_index() == 0. Used by io::load_map. O(end x attributes).
	void restore_lines(uint32 end, std::vector<uint32> free_lines)
	{
		assert(size_ == 0);
		reserve(end);
		size_ = end;
		free_lines_ = std::move(free_lines);
	}

	/// Frees a line: its key becomes INVALID_INDEX and it will be reused.
	void release_line(uint32 i)
	{
		assert(i < size_ && (*key_)[i] != INVALID_INDEX);
		(*key_)[i] = INVALID_INDEX;
		free_lines_.push_back(i);
	}
	/// Frees a line whose key is already INVALID_INDEX (see new_lines_at_end).
	void release_unkeyed_line(uint32 i)
	{
		assert(i < size_ && (*key_)[i] == INVALID_INDEX);
		free_lines_.push_back(i);
	}

	/// Whether line i is in use: below end_index() with a valid key. O(1).
	bool is_live(uint32 i) const
	{
		return i < size_ && (*key_)[i] != INVALID_INDEX;
	}
	/// Number of live lines, O(1).
	uint32 nb_lines() const
	{
		return size_ - uint32(free_lines_.size());
	}
	/// Number of lines allocated (whole chunks): lines in [end_index(),
	/// capacity()) hold their attributes' default values.
	uint32 capacity() const
	{
		return nb_chunks_ * CHUNK_SIZE;
	}
	/// One past the highest line ever used: iterate [0, end_index()) and skip
	/// the lines that are not live.
	uint32 end_index() const
	{
		return size_;
	}
	/// The first live line, or end_index() when there is none. O(number of
	/// free lines before it).
	uint32 first_index() const
	{
		uint32 i = 0;
		while (i < size_ && (*key_)[i] == INVALID_INDEX)
			++i;
		return i;
	}
	/// The first live line after i, or end_index() when there is none.
	/// O(number of free lines skipped).
	uint32 next_index(uint32 i) const
	{
		do
			++i;
		while (i < size_ && (*key_)[i] == INVALID_INDEX);
		return i;
	}
	/// The free lines below end_index(); new_line reuses the last one first.
	const std::vector<uint32>& free_lines() const
	{
		return free_lines_;
	}

	/// Allocates room for n lines in total, so that building does not grow
	/// chunk by chunk.
	void reserve(uint32 n)
	{
		uint32 needed = (n + CHUNK_SIZE - 1) / CHUNK_SIZE;
		if (needed > nb_chunks_)
			set_nb_chunks(needed);
	}

	/// Removes every line (keeps the attributes, frees their memory).
	void clear()
	{
		size_ = 0;
		free_lines_.clear();
		set_nb_chunks(0);
	}

	/// Reserves a cleared mark attribute. Thread-safe. Give it back with
	/// release_mark() after clearing it.
	MarkAttribute* acquire_mark()
	{
		uint64 used = used_slots_.load(std::memory_order_relaxed);
		while (~used != 0)
		{
			uint32 s = uint32(std::countr_zero(~used));
			if (used_slots_.compare_exchange_weak(used, used | (uint64(1) << s), std::memory_order_acquire,
												  std::memory_order_relaxed))
			{
				if (!slots_[s])
				{
					std::lock_guard lock(mutex_);
					slots_[s] = new_mark();
					slots_[s]->set_nb_chunks(nb_chunks_);
					slots_[s]->pool_slot = s;
				}
				return slots_[s].get();
			}
		}
		std::lock_guard lock(mutex_);
		if (overflow_free_.empty())
		{
			overflow_.push_back(new_mark());
			overflow_.back()->set_nb_chunks(nb_chunks_);
			return overflow_.back().get();
		}
		MarkAttribute* m = overflow_free_.back();
		overflow_free_.pop_back();
		return m;
	}
	/// Gives back a mark reserved by acquire_mark(); it must be cleared.
	void release_mark(MarkAttribute* m)
	{
		if (m->pool_slot != INVALID_INDEX)
		{
			used_slots_.fetch_and(~(uint64(1) << m->pool_slot), std::memory_order_release);
			return;
		}
		std::lock_guard lock(mutex_);
		overflow_free_.push_back(m);
	}
	/// Frees the memory of the pooled marks nobody holds (released marks keep
	/// their chunks to be reused at once; a later acquire_mark allocates them
	/// again). Builders call it when they are done, so that the marks a build
	/// used do not stay allocated next to the mesh (one bit per line each).
	/// Not thread-safe: no mark may be acquired or released meanwhile.
	void release_idle_marks()
	{
		std::lock_guard lock(mutex_);
		const uint64 used = used_slots_.load(std::memory_order_acquire);
		for (uint32 s = 0; s < slots_.size(); ++s)
			if (((used >> s) & 1u) == 0)
				slots_[s].reset();
		for (MarkAttribute* idle : overflow_free_)
			std::erase_if(overflow_, [&](const auto& m) { return m.get() == idle; });
		overflow_free_.clear();
	}

	/// A mark attribute owned by the container for its whole life (e.g. the
	/// boundary mark of the darts).
	MarkAttribute* add_persistent_mark()
	{
		persistent_marks_.push_back(new_mark());
		persistent_marks_.back()->set_nb_chunks(nb_chunks_);
		return persistent_marks_.back().get();
	}

	/// Bytes held by attributes and marks (allocated chunks, live or not;
	/// pooled marks too, held or idle).
	std::size_t memory_bytes() const
	{
		std::size_t b = 0;
		for (const auto& a : attributes_)
			b += a->memory_bytes();
		for (const auto& m : persistent_marks_)
			b += m->memory_bytes();
		for (const auto& m : slots_)
			if (m)
				b += m->memory_bytes();
		for (const auto& m : overflow_)
			b += m->memory_bytes();
		return b + free_lines_.capacity() * sizeof(uint32);
	}

	/// Lets every attribute and mark swap two lines (used by compaction and
	/// reordering; the caller keeps the key and the free list consistent).
	void swap_lines(uint32 a, uint32 b)
	{
		for (auto& at : attributes_)
			at->swap_lines(a, b);
		for (auto& m : persistent_marks_)
			m->swap_lines(a, b);
	}
	/// After lines were moved so that the live ones are [0, n): forget the rest.
	/// The lines past n that stay allocated (in the last chunk) get their
	/// default values back, as new_line hands lines at the end out as they are.
	void truncate(uint32 n)
	{
		const uint32 allocated_end = std::min(size_, nb_chunks_ * CHUNK_SIZE);
		for (uint32 i = n; i < allocated_end; ++i)
		{
			for (auto& a : attributes_)
				a->reset_line(i);
			for (auto& m : persistent_marks_)
				m->reset(i);
		}
		size_ = n;
		free_lines_.clear();
		set_nb_chunks((n + CHUNK_SIZE - 1) / CHUNK_SIZE);
	}

	/// Moves the live lines to [0, nb_lines()) keeping their order, frees the
	/// rest and returns old line -> new line (INVALID_INDEX for free lines).
	/// Values follow their lines; callers remap what refers to lines.
	/// Precondition: no mark is reserved. O(lines x attributes).
	std::vector<uint32> compact()
	{
		std::vector<uint32> old_to_new(size_, INVALID_INDEX);
		uint32 n = 0;
		for (uint32 i = 0; i < size_; ++i)
			if ((*key_)[i] != INVALID_INDEX)
			{
				if (n != i)
					swap_lines(n, i); // line n is free (or already moved): its old values do not matter
				old_to_new[i] = n++;
			}
		truncate(n);
		return old_to_new;
	}

	/// Permutes the lines: the line at i goes to new_position[i]. Every line
	/// below end_index() must have a distinct position below end_index().
	/// O(lines x attributes).
	void permute(const std::vector<uint32>& new_position)
	{
		std::vector<uint32> at(new_position.size()); // at[p] = old line now at p during the cycles
		std::vector<uint32> where(new_position.size());
		for (uint32 i = 0; i < at.size(); ++i)
			at[i] = where[i] = i;
		for (uint32 i = 0; i < new_position.size(); ++i)
		{
			// bring old line i to new_position[i]
			const uint32 from = where[i], to = new_position[i];
			if (from == to)
				continue;
			swap_lines(from, to);
			const uint32 other = at[to];
			at[to] = i;
			at[from] = other;
			where[i] = to;
			where[other] = from;
		}
		std::vector<uint32> free_lines;
		for (uint32 i : free_lines_)
			free_lines.push_back(new_position[i]);
		free_lines_ = std::move(free_lines);
	}

private:
	/// Gives a, a new attribute of this container, the container's lines and
	/// cell index, and lists it: the part of add_attribute that does not
	/// depend on the attribute's class. O(attributes + capacity()).
	void adopt(const std::shared_ptr<AttributeBase>& a);

	std::unique_ptr<MarkAttribute> new_mark() const
	{
		return std::make_unique<MarkAttribute>(
			std::min(max_contiguous_lines_, MarkAttribute::default_contiguous_lines()));
	}

	void set_nb_chunks(uint32 n)
	{
		for (auto& a : attributes_)
			a->set_nb_chunks(n);
		for (auto& m : persistent_marks_)
			m->set_nb_chunks(n);
		for (auto& m : slots_)
			if (m)
				m->set_nb_chunks(n);
		for (auto& m : overflow_)
			m->set_nb_chunks(n);
		nb_chunks_ = n;
	}

	uint64 max_contiguous_lines_;
	Orbit orbit_ = Orbit::DART;
	const AttributeArray<uint32>* cell_index_ = nullptr;
	std::vector<std::shared_ptr<AttributeBase>> attributes_;
	std::vector<AttributeBase*> ruled_; ///< The attributes whose rule is not None.
	uint32* map_rule_count_ = nullptr;  ///< See count_rules_in.
	AttributeArray<uint32>* key_ = nullptr;
	uint32 size_ = 0;
	uint32 nb_chunks_ = 0;
	std::vector<uint32> free_lines_;

	std::vector<std::unique_ptr<MarkAttribute>> persistent_marks_;
	std::atomic<uint64> used_slots_{0};
	std::array<std::unique_ptr<MarkAttribute>, 64> slots_;
	std::mutex mutex_;
	std::vector<std::unique_ptr<MarkAttribute>> overflow_;
	std::vector<MarkAttribute*> overflow_free_;
};

/// A mark reserved from a container's pool for the life of its owner and given
/// back when it dies, exceptions included. The owner clears the bits it set
/// before then, in its own way: all at once, or only those it recorded.
class ReservedMark
{
public:
	/// Reserves a cleared mark of container c (see AttributeContainer::acquire_mark).
	explicit ReservedMark(AttributeContainer& c) : container_(c), mark_(c.acquire_mark())
	{
	}
	~ReservedMark()
	{
		container_.release_mark(mark_);
	}
	ReservedMark(const ReservedMark&) = delete;
	ReservedMark& operator=(const ReservedMark&) = delete;

	/// The reserved mark.
	MarkAttribute& operator*() const
	{
		return *mark_;
	}
	/// The reserved mark's members.
	MarkAttribute* operator->() const
	{
		return mark_;
	}

private:
	AttributeContainer& container_;
	MarkAttribute* mark_;
};

// One owner type for every attribute class (std::make_shared would compile a
// control block per class: per value type and orbit).
template <typename T>
std::shared_ptr<AttributeBase> AttributeArray<T>::make(AttributeContainer* container, std::string name, T default_value,
													   uint64 contiguous_lines)
{
	return std::shared_ptr<AttributeBase>(static_cast<AttributeBase*>(
		new AttributeArray<T>(container, std::move(name), std::move(default_value), contiguous_lines)));
}

template <typename T, Orbit O>
std::shared_ptr<AttributeBase> CellAttribute<T, O>::make(AttributeContainer* container, std::string name,
														 T default_value, uint64 contiguous_lines)
{
	return std::shared_ptr<AttributeBase>(static_cast<AttributeBase*>(
		new CellAttribute<T, O>(container, std::move(name), std::move(default_value), contiguous_lines)));
}

template <typename T>
std::shared_ptr<AttributeBase> AttributeArray<T>::with_rule_of_this(std::shared_ptr<AttributeBase> clone,
																	AttributeContainer& to) const
{
	if (clone)
	{
		static_cast<AttributeArray<T>&>(*clone).set_rule_callback(callback_);
		to.set_rule(*clone, rule_);
	}
	return clone;
}

template <typename T>
std::shared_ptr<AttributeBase> AttributeArray<T>::clone_empty(AttributeContainer& to) const
{
	return with_rule_of_this(to.add_attribute<T>(name_, default_value_), to);
}

template <typename T, Orbit O>
std::shared_ptr<AttributeBase> CellAttribute<T, O>::clone_empty(AttributeContainer& to) const
{
	return this->with_rule_of_this(clone_of_kind(to), to);
}

namespace detail
{

/// The orbits of the containers a CellAttribute<T, O> clones into, first
/// match first, padded with NB_ORBITS; O itself last. A container of the
/// same cell kind in the other model of surfaces (the CMap2 <-> GMap2
/// conversions); a graph's vertices and edges, from the vertices and edges
/// of any map (to_graph: its 1-skeleton), and an incidence graph's vertices
/// and edges, from and to those of a 2-map (to_incidence_graph, to_cmap2);
/// then the cells of the same dimension in a map of any dimension, or in a
/// map of dimension 2 or 3 (to_nmap, to_fixed_map).
constexpr std::array<Orbit, 9> clone_orbits(Orbit o)
{
	std::array<Orbit, 9> r{};
	r.fill(Orbit::NB_ORBITS);
	std::size_t n = 0;
	if (surface_counterpart(o) != o)
		r[n++] = surface_counterpart(o);
	const Orbit k = is_dimension_orbit(o)   ? o
					: o == Orbit::IG_VERTEX ? Orbit::CELL0
					: o == Orbit::IG_EDGE   ? Orbit::CELL1
											: dimension_counterpart(o);
	if (k == Orbit::CELL0)
		for (Orbit x : {Orbit::ALPHA1, Orbit::IG_VERTEX, Orbit::PHI21})
			r[n++] = x;
	if (k == Orbit::CELL1)
		for (Orbit x : {Orbit::ALPHA0, Orbit::IG_EDGE, Orbit::PHI2})
			r[n++] = x;
	for (Orbit x : same_dimension_orbits(o))
		if (x != Orbit::NB_ORBITS)
			r[n++] = x;
	r[n] = o;
	return r;
}

/// The factory of CellAttribute<T, X>; nullptr for NB_ORBITS.
template <typename T, Orbit X>
constexpr AttributeContainer::Factory<T> cell_attribute_factory()
{
	if constexpr (X == Orbit::NB_ORBITS)
		return nullptr;
	else
		return &CellAttribute<T, X>::make;
}

} // namespace detail

template <typename T, Orbit O>
std::shared_ptr<AttributeBase> CellAttribute<T, O>::clone_of_kind(AttributeContainer& to) const
{
	// the factories of the candidate classes, then one call: a call per
	// candidate would compile the whole of add_attribute each time, in every
	// attribute class
	constexpr std::array<Orbit, 9> orbits = detail::clone_orbits(O);
	static constexpr std::array<AttributeContainer::Factory<T>, 9> factories =
		[]<std::size_t... I>(std::index_sequence<I...>)
	{
		return std::array<AttributeContainer::Factory<T>, 9>{
			detail::cell_attribute_factory<T, detail::clone_orbits(O)[I]>()...};
	}
	(std::make_index_sequence<9>{});
	for (std::size_t i = 0; i < orbits.size(); ++i)
		if (to.orbit() == orbits[i])
			return to.add_attribute_made_by<T>(factories[i], this->name(), this->default_value());
	assert(false && "clone into a container of another orbit");
	return to.add_attribute_made_by<T>(&CellAttribute<T, O>::make, this->name(), this->default_value());
}

template <typename T>
template <Orbit O>
CGOGN_INLINE uint32 AttributeArray<T>::line_of(Cell<O> c) const
{
	assert(container_ != nullptr && "attribute removed from its map");
	assert(container_->orbit() == O && "attribute indexed by a cell of another orbit");
	if constexpr (O == Orbit::DART || is_direct_orbit(O))
		return c.dart.index; // a dart, or a record (see is_direct_orbit), is its own line
	else
	{
		assert(this->cell_index_ != nullptr && this->cell_index_ == container_->cell_index() && "orbit not indexed");
		return (*this->cell_index_)[c.dart.index];
	}
}

template <typename T>
template <typename FUNC>
void AttributeArray<T>::foreach_live_run(const FUNC& f) const
{
	const AttributeContainer* lines = container();
	if (lines == nullptr) // a removed attribute
		return;
	const AttributeArray<uint32>& key = lines->key();
	// with no free line every line in [first, end) is live: whole runs, no key read
	const bool check_live = !lines->free_lines().empty();
	for (uint32 i = lines->first_index(), end = lines->end_index(); i < end;)
	{
		const uint32 stop = std::min(end, run_end(i));
		if (!check_live)
		{
			f(&(*this)[i], stop - i);
			i = stop;
			continue;
		}
		while (i < stop)
		{
			while (i < stop && key[i] == INVALID_INDEX)
				++i;
			uint32 j = i;
			while (j < stop && key[j] != INVALID_INDEX)
				++j;
			if (j > i)
				f(&(*this)[i], j - i);
			i = j;
		}
	}
}

/// Iterates the values of the live lines of an attribute. It steps with a
/// pointer through each run of lines whose values are at consecutive addresses
/// (one run below 2 GiB of values, then one per block, see LineStorage) and
/// reads the key only when the container has free lines, so that a range-for
/// over a dense attribute costs what a loop over a plain array does: one
/// increment and two pointer compares per value. Iterators compare by the
/// address of their value; end() is one past the last line's value.
template <typename T>
template <bool IS_CONST>
class AttributeArray<T>::basic_iterator
{
	using Attr = std::conditional_t<IS_CONST, const AttributeArray<T>, AttributeArray<T>>;
	using Value = std::conditional_t<IS_CONST, const T, T>;

public:
	using value_type = T;                                ///< The attribute's value type.
	using difference_type = std::ptrdiff_t;              ///< As required of a forward iterator.
	using reference = Value&;                            ///< A reference to a value, const for a const_iterator.
	using iterator_category = std::forward_iterator_tag; ///< A forward iterator.

	basic_iterator() = default;
	/// Positioned at line i (live, or end) of an attribute iterated up to line end.
	CGOGN_INLINE basic_iterator(Attr* a, uint32 i, uint32 end) : attr_(a), end_(end)
	{
		if (a->container() != nullptr)
		{
			key_ = &a->container()->key();
			check_live_ = !a->container()->free_lines().empty();
		}
		if (i < end)
		{
			enter_run(i);
			if (check_live_)
				skip_free_lines();
		}
		else if (end > 0)
		{
			// where the walk over the last run stops
			run_first_line_ = end;
			run_first_value_ = value_ = run_end_ = &(*a)[end - 1] + 1;
		}
	}
	/// The value of the current line.
	CGOGN_INLINE Value& operator*() const
	{
		return *value_;
	}
	/// The value of the current line, for member access.
	CGOGN_INLINE Value* operator->() const
	{
		return value_;
	}
	/// Moves to the next live line. O(1) when the container has no free line,
	/// else O(free lines skipped).
	CGOGN_INLINE basic_iterator& operator++()
	{
		step();
		if (check_live_) [[unlikely]]
			skip_free_lines();
		return *this;
	}
	/// Moves to the next live line; returns the iterator as it was before.
	basic_iterator operator++(int)
	{
		basic_iterator t = *this;
		++*this;
		return t;
	}
	/// Whether both point to the same value (of the same attribute).
	CGOGN_INLINE bool operator==(const basic_iterator& o) const
	{
		return value_ == o.value_;
	}
	/// The line of the current value.
	uint32 index() const
	{
		return run_first_line_ + uint32(value_ - run_first_value_);
	}

private:
	CGOGN_INLINE void step()
	{
		if (++value_ == run_end_) [[unlikely]]
			next_run();
	}
	CGOGN_INLINE void next_run()
	{
		const uint32 i = index();
		if (i < end_)
			enter_run(i);
		// else: value_ is one past the last line's value, as end()'s
	}
	CGOGN_INLINE void enter_run(uint32 i)
	{
		run_first_line_ = i;
		run_first_value_ = value_ = &(*attr_)[i];
		const uint32 run_end = std::min(end_, attr_->run_end(i));
		run_end_ = value_ + (run_end - i);
	}
	void skip_free_lines()
	{
		while (index() < end_ && (*key_)[index()] == INVALID_INDEX)
			step();
	}

	Attr* attr_ = nullptr;
	const AttributeArray<uint32>* key_ = nullptr;
	uint32 end_ = 0;
	bool check_live_ = false;
	Value* value_ = nullptr;
	/// The current run: its first line, that line's value, one past its last value.
	uint32 run_first_line_ = 0;
	Value* run_first_value_ = nullptr;
	Value* run_end_ = nullptr;
};

// A removed attribute (no container) iterates over nothing. Inline, so that
// the extern template declarations of attribute_instances.h, which keep the
// other members out of line, leave range-for loops inlined.
template <typename T>
inline typename AttributeArray<T>::iterator AttributeArray<T>::begin()
{
	return container_ ? iterator(this, container_->first_index(), container_->end_index()) : iterator();
}
template <typename T>
inline typename AttributeArray<T>::iterator AttributeArray<T>::end()
{
	return container_ ? iterator(this, container_->end_index(), container_->end_index()) : iterator();
}
template <typename T>
inline typename AttributeArray<T>::const_iterator AttributeArray<T>::begin() const
{
	return container_ ? const_iterator(this, container_->first_index(), container_->end_index()) : const_iterator();
}
template <typename T>
inline typename AttributeArray<T>::const_iterator AttributeArray<T>::end() const
{
	return container_ ? const_iterator(this, container_->end_index(), container_->end_index()) : const_iterator();
}

} // namespace cgogn

#include <cgogn/core/attributes/attribute_instances.h>
