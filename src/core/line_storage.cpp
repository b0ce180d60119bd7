// SPDX-License-Identifier: MIT
#include <cgogn/core/container/line_storage.h>

#if defined(__unix__) || defined(__APPLE__)
#include <sys/mman.h>
#include <unistd.h>
#define CGOGN_HAS_MMAP 1
#else
#define CGOGN_HAS_MMAP 0
#endif

#include <atomic>

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
	// PROT_NONE + MAP_NORESERVE: address space only, nothing counted against
	// the memory of the process until commit_pages
	void* p = mmap(nullptr, bytes, PROT_NONE, MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE, -1, 0);
	return p == MAP_FAILED ? nullptr : p;
}

void commit_pages(void* p, std::size_t bytes)
{
	if (mprotect(p, bytes, PROT_READ | PROT_WRITE) != 0)
		throw std::bad_alloc();
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
