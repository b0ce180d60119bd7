// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <limits>

namespace cgogn
{

using int8 = std::int8_t;
using int32 = std::int32_t;
using int64 = std::int64_t;
using uint8 = std::uint8_t;
using uint16 = std::uint16_t;
using uint32 = std::uint32_t;
using uint64 = std::uint64_t;

/// Forces inlining of the small hot functions (relation and attribute
/// accessors, the cached row walk, local traversals): GCC otherwise keeps some
/// of them out of line once the caller is large, and then the caller's
/// accumulators live in memory across every call (measured: quick surface
/// smoothing spent its time reloading and storing its sum).
#if defined(__GNUC__) || defined(__clang__)
#define CGOGN_INLINE [[gnu::always_inline]] inline
#else
#define CGOGN_INLINE inline
#endif

/// Asks the processor to start loading the cache line of `address` for a read
/// (a hint: no fault, no effect on the program's results).
#if defined(__GNUC__) || defined(__clang__)
#define CGOGN_PREFETCH(address) __builtin_prefetch(address)
#else
#define CGOGN_PREFETCH(address) ((void)(address))
#endif

/// The value of an index (dart, cell line) that designates nothing.
inline constexpr uint32 INVALID_INDEX = std::numeric_limits<uint32>::max();

} // namespace cgogn
