// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/attributes/line_storage.h>
#include <cgogn/core/map/cell.h>
#include <cgogn/core/utils/numeric.h>

#include <atomic>
#include <cassert>
#include <memory>
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
	AttributeBase(AttributeContainer* container, std::string name) : container_(container), name_(std::move(name))
	{
	}
	virtual ~AttributeBase() = default;
	AttributeBase(const AttributeBase&) = delete;
	AttributeBase& operator=(const AttributeBase&) = delete;

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

	virtual std::type_index type() const = 0;
	virtual void set_nb_chunks(uint32 nb_chunks) = 0;
	virtual void reset_line(uint32 i) = 0;
	virtual void copy_line(uint32 dst, uint32 src) = 0;
	virtual void copy_line_from(uint32 dst, const AttributeBase& other, uint32 src) = 0;
	virtual void swap_lines(uint32 a, uint32 b) = 0;
	virtual std::size_t memory_bytes() const = 0;
	/// A new attribute of the same type, name and default value in container
	/// `to` (nullptr when the name is taken there).
	virtual std::shared_ptr<AttributeBase> clone_empty(AttributeContainer& to) const = 0;

protected:
	friend class AttributeContainer;
	AttributeContainer* container_;
	std::string name_;
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
	using value_type = T;

	/// `contiguous_lines`: see LineStorage (tests lower it to exercise blocks).
	AttributeArray(AttributeContainer* container, std::string name, T default_value = T(),
				   uint64 contiguous_lines = LineStorage<T, CHUNK_SHIFT>::default_contiguous())
		: AttributeBase(container, std::move(name)), values_(contiguous_lines), default_value_(std::move(default_value))
	{
	}

	CGOGN_INLINE T& operator[](uint32 i)
	{
		assert(i < values_.size());
		return values_[i];
	}
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

	/// Sets every allocated line (live or not) to v.
	void fill(const T& v)
	{
		for (uint32 i = 0; i < values_.size(); ++i)
			values_[i] = v;
	}

	template <bool IS_CONST>
	class basic_iterator;
	using iterator = basic_iterator<false>;
	using const_iterator = basic_iterator<true>;
	iterator begin();
	iterator end();
	const_iterator begin() const;
	const_iterator end() const;

protected:
	/// The line of cell c in the attribute's container (defined with AttributeContainer).
	template <Orbit O>
	uint32 line_of(Cell<O> c) const;

private:
	LineStorage<T, CHUNK_SHIFT> values_;
	T default_value_;
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
	static constexpr Orbit ORBIT = O;

	using AttributeArray<T>::AttributeArray;

	CGOGN_INLINE T& operator[](uint32 i)
	{
		return AttributeArray<T>::operator[](i);
	}
	CGOGN_INLINE const T& operator[](uint32 i) const
	{
		return AttributeArray<T>::operator[](i);
	}
	CGOGN_INLINE T& operator[](Cell<O> c)
	{
		return AttributeArray<T>::operator[](c);
	}
	CGOGN_INLINE const T& operator[](Cell<O> c) const
	{
		return AttributeArray<T>::operator[](c);
	}
	CGOGN_INLINE T& operator[](LocatedCell<O> c)
	{
		return AttributeArray<T>::operator[](c);
	}
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
};

/// A bit per line, growing by chunks of the same line count as attributes.
/// Used for markers and the persistent boundary mark. Not safe for concurrent
/// writes to the same 64-line word; parallel traversals give each thread its own.
class MarkAttribute
{
public:
	static constexpr uint32 WORDS_PER_CHUNK = CHUNK_SIZE / 64;

	/// `contiguous_lines`: see LineStorage (tests lower it to exercise blocks).
	explicit MarkAttribute(uint64 contiguous_lines = default_contiguous_lines()) : words_(contiguous_lines / 64)
	{
	}
	static constexpr uint64 default_contiguous_lines()
	{
		return uint64(1) << 28;
	}

	CGOGN_INLINE bool test(uint32 i) const
	{
		return (words_[i >> 6] >> (i & 63u)) & 1u;
	}
	CGOGN_INLINE void set(uint32 i)
	{
		words_[i >> 6] |= (uint64(1) << (i & 63u));
	}
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
	void set_value(uint32 i, bool b)
	{
		if (b)
			set(i);
		else
			reset(i);
	}
	void clear_all()
	{
		for (uint32 w = 0; w < words_.size(); ++w)
			words_[w] = 0;
	}
	bool all_clear() const
	{
		for (uint32 w = 0; w < words_.size(); ++w)
			if (words_[w] != 0)
				return false;
		return true;
	}
	void set_nb_chunks(uint32 nb_chunks)
	{
		words_.resize(nb_chunks * WORDS_PER_CHUNK, 0);
	}
	void swap_lines(uint32 a, uint32 b)
	{
		bool ta = test(a), tb = test(b);
		set_value(a, tb);
		set_value(b, ta);
	}
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
