// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/utils/numeric.h>

#include <algorithm>
#include <cassert>
#include <cstddef>
#include <memory>
#include <new>
#include <vector>

namespace cgogn
{

namespace detail
{

/// Virtual memory for LineStorage. Address space is reserved without backing
/// (no memory is used and nothing is charged until pages are committed), then
/// committed and decommitted page by page as a storage grows and shrinks.
/// On a platform without mmap, reserving returns nullptr and storages keep
/// all their lines in separately allocated blocks.
void* reserve_address_space(std::size_t bytes);
/// Makes [p, p + bytes) readable and writable; throws std::bad_alloc when the
/// system refuses. p and bytes are multiples of the page size.
void commit_pages(void* p, std::size_t bytes);
/// Gives the memory of [p, p + bytes) back to the system; the range stays reserved.
void decommit_pages(void* p, std::size_t bytes);
void release_address_space(void* p, std::size_t bytes);
std::size_t page_size();

} // namespace detail

/// Bytes of committed pages held by all the LineStorages of the process (the
/// attributes and marks of every map): memory the allocator does not see, for
/// tools and benchmarks that account memory with mallinfo. Thread-safe.
std::size_t committed_storage_bytes();

/// The values of one attribute (or the words of one mark): elements
/// [0, size()) that never move once created, whatever the storage grows to.
///
/// Why not a vector of fixed-size blocks: with blocks, reaching element i
/// first loads the address of its block, a dependent load on every step of a
/// traversal (phi2, then the vertex index at phi2(d), then phi1 ...). Measured
/// on the surface suite's smoothing, that load made the walk 1.7x slower than
/// the same walk over plain arrays. So the first `contiguous` elements live at
/// the start of one reserved range of address space (one add, no load), whose
/// pages are committed as the storage grows, and only elements beyond it (a
/// container of more than ~10^8 lines) go to separately allocated blocks of
/// 2^BLOCK_SHIFT elements. Elements never move: the reservation is made once
/// and blocks are never reallocated.
///
/// The size only grows or shrinks by whole blocks. Not thread-safe for resize.
template <typename T, uint32 BLOCK_SHIFT>
class LineStorage
{
public:
	static constexpr uint32 BLOCK_SIZE = 1u << BLOCK_SHIFT; ///< Elements per block; the size is a multiple of it.

	/// `contiguous`: how many elements live in the reserved range (rounded down
	/// to whole blocks); 0 puts every element in blocks.
	explicit LineStorage(uint64 contiguous = default_contiguous())
		: contiguous_target_(contiguous / BLOCK_SIZE * BLOCK_SIZE)
	{
	}
	~LineStorage()
	{
		// the committed pages given back in one call, not block by block
		blocks_.clear();
		if (base_ != nullptr)
		{
			std::destroy_n(base_, contiguous_);
			if (committed_bytes_ > 0)
				detail::decommit_pages(base_, committed_bytes_);
			detail::release_address_space(base_, reserved_bytes());
		}
	}
	LineStorage(const LineStorage&) = delete;
	LineStorage& operator=(const LineStorage&) = delete;

	/// Elements in the reserved range for T: 2 GiB of address space, at most
	/// 2^28 elements (2^28 darts is a 90M-triangle mesh; larger containers
	/// continue in blocks).
	static constexpr uint64 default_contiguous()
	{
		const uint64 by_bytes = (uint64(1) << 31) / sizeof(T);
		return by_bytes < (uint64(1) << 28) ? by_bytes : (uint64(1) << 28);
	}

	// base_ is read before the test, on both paths: read only after it, the
	// load is conditional and GCC does not hoist it out of a loop, so a walk
	// that reads an attribute through value() loaded base_ again at every
	// step (surface smoothing 8% and normal 6% slower, docs/performance.md).
	/// Element i, i < size() (asserted for an element in a block). O(1): a
	/// compare and an add for the elements of the reserved range, one more
	/// load for an element in a block.
	CGOGN_INLINE T& operator[](uint32 i)
	{
		T* const base = base_;
		if (i < contiguous_) [[likely]]
			return base[i];
		return in_block(i);
	}
	/// Element i, read-only; as the overload above.
	CGOGN_INLINE const T& operator[](uint32 i) const
	{
		const T* const base = base_;
		if (i < contiguous_) [[likely]]
			return base[i];
		return in_block(i);
	}

	/// Where the elements are, copied for a loop that reads many of them while
	/// the storage does not grow or shrink. Why: the compiler reloads a
	/// storage's base and bound from memory at every access in a loop whose
	/// earlier statements may leave it (it cannot prove the load safe to
	/// hoist); a view held in a local keeps them in registers.
	class View
	{
	public:
		/// Element i of the storage, as LineStorage::operator[]. O(1).
		CGOGN_INLINE const T& operator[](uint32 i) const
		{
			if (i < contiguous_) [[likely]]
				return base_[i];
			return storage_->in_block(i);
		}

	private:
		friend class LineStorage;
		View(const T* base, uint32 contiguous, const LineStorage* storage)
			: base_(base), contiguous_(contiguous), storage_(storage)
		{
		}
		const T* base_;
		uint32 contiguous_;
		const LineStorage* storage_;
	};
	/// A view of the elements, valid while the storage does not grow or shrink.
	CGOGN_INLINE View view() const
	{
		return View(base_, contiguous_, this);
	}

	/// One past the last element of the run of consecutive addresses that holds
	/// element i (i < size()): &(*this)[i] + k is element i + k for every
	/// i + k < run_end(i). Lets a walk over the elements step with a pointer.
	uint32 run_end(uint32 i) const
	{
		assert(i < size_);
		if (i < contiguous_)
			return contiguous_;
		return contiguous_ + ((i - contiguous_) / BLOCK_SIZE + 1) * BLOCK_SIZE;
	}

	/// Number of elements (a multiple of BLOCK_SIZE).
	uint32 size() const
	{
		return size_;
	}

	/// Grows or shrinks to n elements (a multiple of BLOCK_SIZE): new elements
	/// are copies of `value`, removed ones are destroyed and their memory given
	/// back. The pages of the reserved range are committed (decommitted) in one
	/// call per resize, not one per block: a load that sizes a container of
	/// 10^6 lines at once makes one system call, not hundreds. Throws
	/// std::bad_alloc when memory runs out (the size is then unchanged).
	void resize(uint32 n, const T& value)
	{
		assert(n % BLOCK_SIZE == 0);
		if (n > size_)
		{
			commit_contiguous(n);
			while (size_ < n)
				grow_one_block(value);
		}
		else if (n < size_)
		{
			while (size_ > n)
				shrink_one_block();
			const std::size_t kept = round_to_pages(std::size_t(contiguous_) * sizeof(T));
			if (kept < committed_bytes_)
			{
				detail::decommit_pages(reinterpret_cast<char*>(base_) + kept, committed_bytes_ - kept);
				committed_bytes_ = kept;
			}
		}
	}

	/// Bytes of memory held: committed pages and blocks.
	std::size_t memory_bytes() const
	{
		return committed_bytes_ + blocks_.size() * BLOCK_SIZE * sizeof(T);
	}

private:
	std::size_t reserved_bytes() const
	{
		return round_to_pages(contiguous_target_ * sizeof(T));
	}
	static std::size_t round_to_pages(std::size_t bytes)
	{
		const std::size_t p = detail::page_size();
		return (bytes + p - 1) / p * p;
	}

	// Commits the pages of the reserved range that n elements need (those
	// of the range; the others go to blocks), reserving the range first.
	void commit_contiguous(uint32 n)
	{
		if (size_ >= contiguous_target_)
			return;
		if (base_ == nullptr)
		{
			base_ = static_cast<T*>(detail::reserve_address_space(reserved_bytes()));
			if (base_ == nullptr)
			{
				contiguous_target_ = 0; // no virtual memory: blocks only
				return;
			}
		}
		const std::size_t needed = round_to_pages(std::size_t(std::min<uint64>(n, contiguous_target_)) * sizeof(T));
		if (needed > committed_bytes_)
		{
			detail::commit_pages(reinterpret_cast<char*>(base_) + committed_bytes_, needed - committed_bytes_);
			committed_bytes_ = needed;
		}
	}

	// Precondition: commit_contiguous covered the new block when it goes to
	// the reserved range.
	void grow_one_block(const T& value)
	{
		if (size_ < contiguous_target_)
		{
			if (base_ != nullptr)
			{
				assert(round_to_pages(std::size_t(size_ + BLOCK_SIZE) * sizeof(T)) <= committed_bytes_);
				T* first = base_ + size_;
				std::uninitialized_fill_n(first, BLOCK_SIZE, value);
				size_ += BLOCK_SIZE;
				contiguous_ = size_;
				return;
			}
		}
		auto block = std::make_unique<T[]>(BLOCK_SIZE);
		for (uint32 i = 0; i < BLOCK_SIZE; ++i)
			block[i] = value;
		blocks_.push_back(std::move(block));
		size_ += BLOCK_SIZE;
	}

	void shrink_one_block()
	{
		if (!blocks_.empty())
		{
			blocks_.pop_back();
			size_ -= BLOCK_SIZE;
			return;
		}
		size_ -= BLOCK_SIZE;
		contiguous_ = size_;
		std::destroy_n(base_ + size_, BLOCK_SIZE);
	}

	// Inline, no call: a call in a traversal loop, even on this cold path,
	// may write memory as far as the compiler knows, so base_ and contiguous_
	// of every storage the loop reads were loaded again at each access; on an
	// AMD EPYC that made the library's vertex walk (bench_dart_layout) 145 ms
	// where the same walk over the same memory through plain pointers took 100.
	CGOGN_INLINE T& in_block(uint32 i) const
	{
		assert(i >= contiguous_ && i < size_);
		const uint32 j = i - contiguous_;
		return blocks_[j >> BLOCK_SHIFT][j & (BLOCK_SIZE - 1)];
	}

	T* base_ = nullptr;
	/// Elements [0, contiguous_) are at base_; 0 until the range is reserved.
	uint32 contiguous_ = 0;
	uint32 size_ = 0;
	uint64 contiguous_target_;
	std::size_t committed_bytes_ = 0;
	std::vector<std::unique_ptr<T[]>> blocks_;
};

} // namespace cgogn
