// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/attributes/attribute_rule.h>
#include <cgogn/core/attributes/line_storage.h>
#include <cgogn/core/map/cell.h>
#include <cgogn/core/utils/numeric.h>

#include <atomic>
#include <cassert>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <typeindex>
#include <vector>

namespace cgogn
{

/// Containers grow and shrink by chunks of 2^12 lines. Elements never move
/// when a container grows; access to line i is one add (see LineStorage).
inline constexpr uint32 CHUNK_SHIFT = 12;
inline constexpr uint32 CHUNK_SIZE = 1u << CHUNK_SHIFT;
inline constexpr uint32 CHUNK_MASK = CHUNK_SIZE - 1u;

class AttributeContainer;
template <typename T>
class AttributeArray;

/// Type-erased part of an attribute: what a container needs to grow it, reset
/// or copy lines, and find it by name and type.
class AttributeBase
{
public:
	/// An attribute of `container` named `name`, with no line yet: the container
	/// allocates its lines (set_nb_chunks) when it adds it.
	AttributeBase(AttributeContainer* container, std::string name) : container_(container), name_(std::move(name))
	{
	}
	virtual ~AttributeBase() = default;
	AttributeBase(const AttributeBase&) = delete;
	AttributeBase& operator=(const AttributeBase&) = delete;

	/// The name, unique among the attributes of the container.
	const std::string& name() const
	{
		return name_;
	}
	/// The container that owns the attribute; nullptr once the attribute was
	/// removed (a removed attribute keeps its values until its last handle dies).
	AttributeContainer* container() const
	{
		return container_;
	}

	/// The type of the values (typeid(T)); get_attribute compares it.
	virtual std::type_index type() const = 0;
	/// Resizes to nb_chunks * CHUNK_SIZE lines: new lines get the default
	/// value, lines past the new size are destroyed and their memory given back.
	/// Called by the container, which keeps all its attributes at the same
	/// size. O(lines added or removed). Throws std::bad_alloc when memory runs
	/// out.
	virtual void set_nb_chunks(uint32 nb_chunks) = 0;
	/// Sets line i back to the default value. O(1).
	virtual void reset_line(uint32 i) = 0;
	/// Copies the value of line src to line dst. O(1).
	virtual void copy_line(uint32 dst, uint32 src) = 0;
	/// Copies the value of line src of `other`, an attribute of the same type
	/// (asserted) possibly in another container, to line dst. O(1).
	virtual void copy_line_from(uint32 dst, const AttributeBase& other, uint32 src) = 0;
	/// Exchanges the values of lines a and b. O(1).
	virtual void swap_lines(uint32 a, uint32 b) = 0;
	/// Bytes of memory the values hold (see LineStorage::memory_bytes): all
	/// allocated lines, live or not.
	virtual std::size_t memory_bytes() const = 0;
	/// A new attribute of the same type, name, default value and rule in
	/// container `to` (nullptr when the name is taken there).
	virtual std::shared_ptr<AttributeBase> clone_empty(AttributeContainer& to) const = 0;

	/// What a cell created by an operator gets in this attribute (see
	/// attribute_rules.h); set through the container, which keeps the list of
	/// the attributes that have a rule.
	AttributeRule rule() const
	{
		return rule_;
	}
	/// Applies the rule to line dst from the parent lines `src` and their
	/// weights `w` (as many, summing to 1, dst possibly among the parents):
	/// Copy takes the value of the parent of largest weight (the first of
	/// equals), Interpolate the weighted sum for linear types (else as Copy),
	/// Callback calls the attribute's callback. Nothing for None, or when src
	/// is empty. O(number of parents).
	virtual void apply_rule(uint32 dst, std::span<const uint32> src, std::span<const double> w) = 0;

protected:
	friend class AttributeContainer;
	AttributeContainer* container_;            ///< See container().
	std::string name_;                         ///< See name().
	AttributeRule rule_ = AttributeRule::None; ///< See rule().
	/// The container's cell index (see AttributeContainer::cell_index), kept
	/// here so that `attr[c]` costs the loads value() costs.
	const AttributeArray<uint32>* cell_index_ = nullptr;
};

/// A typed attribute: one value of type T per line of its container (see
/// LineStorage for where values live). `(*attr)[i]` is the value of line i,
/// `(*attr)[c]` the value of cell c (see below); a range-for visits the values
/// of the live lines. This is `mesh_traits<M>::Attribute<T>` for every map;
/// add_attribute and get_attribute return the derived CellAttribute<T, O>,
/// which also knows its orbit at compile time.
template <typename T>
class AttributeArray : public AttributeBase
{
public:
	using value_type = T; ///< The type of the values.
	/// A user rule: sets `value` (the new cell's, holding the default value
	/// or, for a merge, the surviving cell's) from the parents' values and
	/// weights.
	using RuleCallback = std::function<void(T& value, std::span<const T> parents, std::span<const double> weights)>;

	/// `contiguous_lines`: see LineStorage (tests lower it to exercise blocks).
	AttributeArray(AttributeContainer* container, std::string name, T default_value = T(),
				   uint64 contiguous_lines = LineStorage<T, CHUNK_SHIFT>::default_contiguous())
		: AttributeBase(container, std::move(name)), values_(contiguous_lines), default_value_(std::move(default_value))
	{
	}

	/// A new attribute of this class, owned by a std::shared_ptr, with no line
	/// yet (AttributeContainer::add_attribute allocates them). Each attribute
	/// class has its own: defined with AttributeContainer, out of the class,
	/// so that the library compiles it once for the common value types (see
	/// attribute_instances.h).
	static std::shared_ptr<AttributeBase> make(AttributeContainer* container, std::string name, T default_value,
											   uint64 contiguous_lines);

	/// The value of line i, live or not; i must be below the container's
	/// capacity() (asserted). O(1): a compare and an add (one more load for a
	/// line beyond the reserved range, see LineStorage).
	CGOGN_INLINE T& operator[](uint32 i)
	{
		assert(i < values_.size());
		return values_[i];
	}
	/// The value of line i, read-only; as the overload above.
	CGOGN_INLINE const T& operator[](uint32 i) const
	{
		assert(i < values_.size());
		return values_[i];
	}

	/// The value of cell c: the line its map gives c (index_of), then that
	/// line's value; the same loads as value(m, attr, c). O(1).
	/// Preconditions (asserted): the attribute still belongs to its map and c
	/// is a cell of the attribute's orbit. Through a CellAttribute<T, O> (the
	/// handles add_attribute and get_attribute return) a cell of another orbit
	/// does not compile; through this orbit-erased type only the assertion
	/// checks it.
	template <Orbit O>
	CGOGN_INLINE T& operator[](Cell<O> c)
	{
		return (*this)[line_of(c)];
	}
	/// The value of cell c, read-only; as the overload above.
	template <Orbit O>
	CGOGN_INLINE const T& operator[](Cell<O> c) const
	{
		return (*this)[line_of(c)];
	}
	/// The same for a cell reported with its line (a cached traversal, or
	/// foreach_cell with a `Located<CELL>` parameter): no index lookup.
	template <Orbit O>
	CGOGN_INLINE T& operator[](LocatedCell<O> c)
	{
		assert(c.line == line_of(Cell<O>(c)) && "stale cell line");
		return (*this)[c.line];
	}
	/// The value of a located cell, read-only; as the overload above.
	template <Orbit O>
	CGOGN_INLINE const T& operator[](LocatedCell<O> c) const
	{
		assert(c.line == line_of(Cell<O>(c)) && "stale cell line");
		return (*this)[c.line];
	}

	/// A read-only view of the values for a loop in which the attribute does
	/// not grow (see LineStorage::View).
	CGOGN_INLINE typename LineStorage<T, CHUNK_SHIFT>::View view() const
	{
		return values_.view();
	}

	/// One past the last line of the run of lines whose values are at
	/// consecutive addresses from line i's (see LineStorage::run_end).
	uint32 run_end(uint32 i) const
	{
		return values_.run_end(i);
	}

	/// Calls f(first, count) on each stretch of live lines whose values are at
	/// consecutive addresses, in line order: `count` values from `first` (a
	/// `const T*`). The range-for's walk, handed out as plain arrays for loops
	/// that want them (several accumulators, SIMD); the key is read only when
	/// the container has free lines.
	template <typename FUNC>
	void foreach_live_run(const FUNC& f) const;

	/// The value given to lines when they are created.
	const T& default_value() const
	{
		return default_value_;
	}

	std::type_index type() const override
	{
		return typeid(T);
	}
	void set_nb_chunks(uint32 nb_chunks) override
	{
		values_.resize(nb_chunks * CHUNK_SIZE, default_value_);
	}
	void reset_line(uint32 i) override
	{
		(*this)[i] = default_value_;
	}
	void copy_line(uint32 dst, uint32 src) override
	{
		(*this)[dst] = (*this)[src];
	}
	void copy_line_from(uint32 dst, const AttributeBase& other, uint32 src) override
	{
		assert(other.type() == type());
		(*this)[dst] = static_cast<const AttributeArray<T>&>(other)[src];
	}
	void swap_lines(uint32 a, uint32 b) override
	{
		using std::swap;
		swap((*this)[a], (*this)[b]);
	}
	std::size_t memory_bytes() const override
	{
		return values_.memory_bytes();
	}
	std::shared_ptr<AttributeBase> clone_empty(AttributeContainer& to) const override;

	void apply_rule(uint32 dst, std::span<const uint32> src, std::span<const double> w) override
	{
		if (src.empty())
			return;
		switch (rule_)
		{
		case AttributeRule::None:
			return;
		case AttributeRule::Interpolate:
			if constexpr (LinearValue<T>)
			{
				(*this)[dst] = detail::linear_combination<T>(
					src.size(), [&](std::size_t k) -> const T& { return (*this)[src[k]]; }, w);
				return;
			}
			[[fallthrough]];
		case AttributeRule::Copy: {
			const uint32 from = src[detail::heaviest(w)];
			if (from != dst)
				(*this)[dst] = (*this)[from];
			return;
		}
		case AttributeRule::Callback: {
			// an array, not a std::vector (whose bool specialization has no span)
			const auto parents = std::make_unique<T[]>(src.size());
			for (std::size_t k = 0; k < src.size(); ++k)
				parents[k] = (*this)[src[k]];
			callback_((*this)[dst], std::span<const T>(parents.get(), src.size()), w);
			return;
		}
		}
	}
	/// The user rule, when rule() is Callback.
	const RuleCallback& rule_callback() const
	{
		return callback_;
	}
	/// Sets the user rule; the container's set_rule(attr, Callback) makes it
	/// the attribute's rule.
	void set_rule_callback(RuleCallback f)
	{
		callback_ = std::move(f);
	}

	/// Sets every allocated line (live or not) to v.
	void fill(const T& v)
	{
		for (uint32 i = 0; i < values_.size(); ++i)
			values_[i] = v;
	}

	template <bool IS_CONST>
	class basic_iterator;
	using iterator = basic_iterator<false>;      ///< Iterates the values of the live lines.
	using const_iterator = basic_iterator<true>; ///< Iterates the values of the live lines, read-only.
	/// The value of the first live line. O(number of free lines before it).
	/// A removed attribute (no container) iterates over nothing.
	iterator begin();
	/// One past the value of the last line below the container's end_index(). O(1).
	iterator end();
	/// The value of the first live line, read-only; as the overload above.
	const_iterator begin() const;
	/// One past the value of the last line, read-only; as the overload above.
	const_iterator end() const;

protected:
	/// The line of cell c in the attribute's container (defined with AttributeContainer).
	template <Orbit O>
	uint32 line_of(Cell<O> c) const;
	/// Gives `clone` (nullptr, or an attribute of type T in container `to`)
	/// this attribute's rule and rule callback, and returns it: the part of
	/// clone_empty common to every orbit (defined with AttributeContainer).
	std::shared_ptr<AttributeBase> with_rule_of_this(std::shared_ptr<AttributeBase> clone,
													 AttributeContainer& to) const;

private:
	LineStorage<T, CHUNK_SHIFT> values_;
	T default_value_;
	RuleCallback callback_;
};

/// The attribute handle add_attribute<T, CELL> and get_attribute<T, CELL>
/// return: an AttributeArray<T> whose orbit O (CELL::ORBIT) is part of its
/// type, so that `(*attr)[c]` accepts the cells of that orbit only; a cell of
/// another orbit is a compile error. `(*attr)[c]` costs what value(m, attr, c)
/// costs. It converts to std::shared_ptr<mesh_traits<M>::Attribute<T>>.
template <typename T, Orbit O>
class CellAttribute : public AttributeArray<T>
{
public:
	static constexpr Orbit ORBIT = O; ///< The orbit of the cells that own the lines.

	using AttributeArray<T>::AttributeArray;

	/// A new attribute of this class (see AttributeArray::make).
	static std::shared_ptr<AttributeBase> make(AttributeContainer* container, std::string name, T default_value,
											   uint64 contiguous_lines);

	/// The value of line i (see AttributeArray::operator[](uint32)). O(1).
	CGOGN_INLINE T& operator[](uint32 i)
	{
		return AttributeArray<T>::operator[](i);
	}
	/// The value of line i, read-only. O(1).
	CGOGN_INLINE const T& operator[](uint32 i) const
	{
		return AttributeArray<T>::operator[](i);
	}
	/// The value of cell c, a cell of the attribute's orbit (see
	/// AttributeArray::operator[](Cell<O>)). O(1).
	CGOGN_INLINE T& operator[](Cell<O> c)
	{
		return AttributeArray<T>::operator[](c);
	}
	/// The value of cell c, read-only. O(1).
	CGOGN_INLINE const T& operator[](Cell<O> c) const
	{
		return AttributeArray<T>::operator[](c);
	}
	/// The value of a cell reported with its line: no index lookup. O(1).
	CGOGN_INLINE T& operator[](LocatedCell<O> c)
	{
		return AttributeArray<T>::operator[](c);
	}
	/// The value of a cell reported with its line, read-only. O(1).
	CGOGN_INLINE const T& operator[](LocatedCell<O> c) const
	{
		return AttributeArray<T>::operator[](c);
	}
	/// A cell of another orbit: rejected at compile time.
	template <Orbit P>
	requires(P != O) void operator[](Cell<P>) const
	{
		static_assert(P == O, "attribute indexed by a cell of another orbit than its own");
	}

	std::shared_ptr<AttributeBase> clone_empty(AttributeContainer& to) const override;

private:
	/// clone_empty without the rule: an attribute of the orbit of `to`'s kind.
	std::shared_ptr<AttributeBase> clone_of_kind(AttributeContainer& to) const;
};

/// A bit per line, growing by chunks of the same line count as attributes.
/// Used for markers and the persistent boundary mark. Not safe for concurrent
/// writes to the same 64-line word; parallel traversals give each thread its own.
class MarkAttribute
{
public:
	static constexpr uint32 WORDS_PER_CHUNK = CHUNK_SIZE / 64; ///< 64-bit words holding the bits of a chunk.

	/// `contiguous_lines`: see LineStorage (tests lower it to exercise blocks).
	explicit MarkAttribute(uint64 contiguous_lines = default_contiguous_lines()) : words_(contiguous_lines / 64)
	{
	}
	/// Lines whose bits live in the reserved range by default: 2^28, as for a
	/// uint32 attribute (32 MiB of address space, committed only as used).
	static constexpr uint64 default_contiguous_lines()
	{
		return uint64(1) << 28;
	}

	/// Whether the bit of line i is set. O(1); not atomic.
	CGOGN_INLINE bool test(uint32 i) const
	{
		return (words_[i >> 6] >> (i & 63u)) & 1u;
	}
	/// Sets the bit of line i. O(1); not atomic.
	CGOGN_INLINE void set(uint32 i)
	{
		words_[i >> 6] |= (uint64(1) << (i & 63u));
	}
	/// Clears the bit of line i. O(1); not atomic.
	CGOGN_INLINE void reset(uint32 i)
	{
		words_[i >> 6] &= ~(uint64(1) << (i & 63u));
	}
	/// Atomic (relaxed) access, for a mark shared by the threads of a parallel
	/// traversal: while threads share the mark, every access goes through these.
	bool atomic_test(uint32 i) const
	{
		return (word_ref(i).load(std::memory_order_relaxed) >> (i & 63u)) & 1u;
	}
	/// Sets bit i atomically; true when this call set it (it was clear).
	bool atomic_test_and_set(uint32 i)
	{
		const uint64 bit = uint64(1) << (i & 63u);
		return (word_ref(i).fetch_or(bit, std::memory_order_relaxed) & bit) == 0;
	}
	/// Sets bit i with a relaxed atomic load and store, no read-modify-write:
	/// cheaper than atomic_test_and_set, but a set of another bit of the same
	/// word by another thread at the same moment may be lost. For hints only
	/// (e.g. "no need to look at this dart again"), never for decisions.
	void atomic_set_lossy(uint32 i)
	{
		std::atomic_ref<uint64> w = word_ref(i);
		w.store(w.load(std::memory_order_relaxed) | (uint64(1) << (i & 63u)), std::memory_order_relaxed);
	}
	/// Sets the bit of line i to b. O(1); not atomic.
	void set_value(uint32 i, bool b)
	{
		if (b)
			set(i);
		else
			reset(i);
	}
	/// Clears every bit, live lines or not. O(capacity / 64).
	void clear_all()
	{
		for (uint32 w = 0; w < words_.size(); ++w)
			words_[w] = 0;
	}
	/// Whether no bit is set. O(capacity / 64).
	bool all_clear() const
	{
		for (uint32 w = 0; w < words_.size(); ++w)
			if (words_[w] != 0)
				return false;
		return true;
	}
	/// Resizes to nb_chunks * CHUNK_SIZE lines; the bits of new lines are
	/// clear. Called by the container, with the size of its attributes.
	/// O(words added or removed).
	void set_nb_chunks(uint32 nb_chunks)
	{
		words_.resize(nb_chunks * WORDS_PER_CHUNK, 0);
	}
	/// Exchanges the bits of lines a and b. O(1); not atomic.
	void swap_lines(uint32 a, uint32 b)
	{
		bool ta = test(a), tb = test(b);
		set_value(a, tb);
		set_value(b, ta);
	}
	/// Bytes of memory held by the bits (see LineStorage::memory_bytes).
	std::size_t memory_bytes() const
	{
		return words_.memory_bytes();
	}

	/// Slot of the container's lock-free pool that owns this mark, if any.
	uint32 pool_slot = INVALID_INDEX;

private:
	std::atomic_ref<uint64> word_ref(uint32 i) const
	{
		return std::atomic_ref<uint64>(const_cast<uint64&>(words_[i >> 6]));
	}

	LineStorage<uint64, CHUNK_SHIFT - 6> words_;
};

} // namespace cgogn
