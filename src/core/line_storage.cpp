// SPDX-License-Identifier: MIT
#include <cgogn/core/attributes/line_storage.h>

#if defined(__unix__) || defined(__APPLE__)
#include <sys/mman.h>
#include <unistd.h>
#define CGOGN_HAS_MMAP 1
#else
#define CGOGN_HAS_MMAP 0
#endif

#include <atomic>
#include <cstdint>

namespace cgogn
{

namespace
{
std::atomic<std::size_t> committed_bytes{0};
}

std::size_t committed_storage_bytes()
{
	return committed_bytes.load(std::memory_order_relaxed);
}

namespace detail
{

#if CGOGN_HAS_MMAP

void* reserve_address_space(std::size_t bytes)
{
	if (bytes == 0)
		return nullptr;
	// Each range starts 37 pages further, modulo 2 MiB, than the previous one.
	// Why: the storages of a map are walked together at nearby lines (phi2 of
	// d, the vertex line at phi2(d), phi1, the position), and equal-sized
	// reservations placed next to each other start at exact multiples of 1 GiB
	// apart, so line i of every storage has the same address bits 12-29. On an
	// AMD EPYC that made the library's vertex walk (bench_dart_layout) 203 ms
	// against 147 ms with staggered starts; plain arrays in such aligned
	// reservations took 136-172 ms against 101-109 ms staggered.
	static std::atomic<uint32> reservations{0};
	const std::size_t page = page_size();
	const std::size_t span = 512 * page;
	const std::size_t shift = std::size_t(reservations.fetch_add(1, std::memory_order_relaxed) * 37u % 512u) * page;
	const std::size_t mapped = bytes + 2 * span;
	// PROT_NONE + MAP_NORESERVE: address space only, nothing counted against
	// the memory of the process until commit_pages
	void* m = mmap(nullptr, mapped, PROT_NONE, MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE, -1, 0);
	if (m == MAP_FAILED)
		return nullptr;
	char* const raw = static_cast<char*>(m);
	const std::uintptr_t aligned = (reinterpret_cast<std::uintptr_t>(raw) + span - 1) / span * span;
	char* const p = raw + (aligned - reinterpret_cast<std::uintptr_t>(raw)) + shift;
	// keep exactly [p, p + bytes) reserved
	if (p > raw)
		munmap(raw, std::size_t(p - raw));
	char* const tail = p + bytes;
	if (tail < raw + mapped)
		munmap(tail, std::size_t(raw + mapped - tail));
	return p;
}

void commit_pages(void* p, std::size_t bytes)
{
	if (mprotect(p, bytes, PROT_READ | PROT_WRITE) != 0)
		throw std::bad_alloc();
#ifdef MADV_HUGEPAGE
	// A range that can hold a 2 MiB page is backed by such pages where the
	// system allows them (transparent huge pages in "madvise" mode, Debian's
	// default): one fault and one TLB entry per 2 MiB instead of 512. The
	// pages are only ever inside the committed range, and every page of it is
	// written anyway, so this takes no extra memory. Loading a 1M-face map
	// from a .cgmap file went from 81 to 54 ms, most of it in the kernel.
	if (bytes >= 512 * page_size())
		madvise(p, bytes, MADV_HUGEPAGE);
#endif
#ifdef MADV_POPULATE_WRITE
	// the caller writes every element of the range at once (LineStorage
	// fills new lines): the kernel maps the pages in one call instead of one
	// fault per page. A kernel without it (before Linux 5.14) faults them in.
	if (bytes >= 64 * page_size())
		madvise(p, bytes, MADV_POPULATE_WRITE);
#endif
	committed_bytes.fetch_add(bytes, std::memory_order_relaxed);
}

void decommit_pages(void* p, std::size_t bytes)
{
	// the pages go back to the system; the range becomes inaccessible again
	// so that a stale access faults instead of reading zeros
	madvise(p, bytes, MADV_DONTNEED);
	mprotect(p, bytes, PROT_NONE);
	committed_bytes.fetch_sub(bytes, std::memory_order_relaxed);
}

void release_address_space(void* p, std::size_t bytes)
{
	munmap(p, bytes);
}

std::size_t page_size()
{
	static const std::size_t size = std::size_t(sysconf(_SC_PAGESIZE));
	return size;
}

#else

void* reserve_address_space(std::size_t)
{
	return nullptr;
}
void commit_pages(void*, std::size_t)
{
}
void decommit_pages(void*, std::size_t)
{
}
void release_address_space(void*, std::size_t)
{
}
std::size_t page_size()
{
	return 4096;
}

#endif

} // namespace detail

} // namespace cgogn
