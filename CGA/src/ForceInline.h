// BOOSTED_FORCE_INLINE: the kernel's small hot functions (lane operators, dual-number operations,
// sparse product terms, the core's pieces) are inlined whatever the compiler's size budget: GCC
// otherwise leaves some out of line in the long functions of PointMapCore.h, and an out-of-line
// call passes its lane vectors through memory (measured: a third of the derivative's
// instructions). Under AddressSanitizer and in the coverage build (BOOSTED_PLAIN_INLINE, set by
// BOOSTEDSURFACES_COVERAGE) it is a plain `inline`: forcing the instrumented code into one body
// made the AVX2 kernel file take 416 s to compile instead of 26 s under ASan (more than 17
// minutes with gcov's counters), and inlining changes no result (the core is compiled with
// -ffp-contract=off).
#pragma once

#if defined(__SANITIZE_ADDRESS__) && !defined(BOOSTED_PLAIN_INLINE)
#define BOOSTED_PLAIN_INLINE 1
#endif

#if (defined(__GNUC__) || defined(__clang__)) && !defined(BOOSTED_PLAIN_INLINE)
#define BOOSTED_FORCE_INLINE inline __attribute__((always_inline))
#else
#define BOOSTED_FORCE_INLINE inline
#endif

// BOOSTED_LANE_INLINE: always inlined, under the sanitizers too. The lane helpers (LaneClones.h,
// ConformalLanes.h and their users) pass GCC's 64-byte vectors by value, whose calling convention
// differs between an AVX-512 lane clone and a default-target copy of the helper (-Wpsabi): an
// out-of-line call mixes the two (the ASan build, where BOOSTED_FORCE_INLINE is a plain inline,
// called derivativeLanes out of line and read its arguments shifted by the hidden return pointer).
#if defined(__GNUC__) || defined(__clang__)
#define BOOSTED_LANE_INLINE inline __attribute__((always_inline))
#else
#define BOOSTED_LANE_INLINE inline
#endif

// BOOSTED_COLD: a rare branch kept out of line (and out of the hot code's cache lines), so that its
// code does not enter the register allocation of the common path that calls it (PointMapCore.h's
// strong branch: inlined, it cost the common path about 4 ns per point on AVX-512).
#if defined(__GNUC__) || defined(__clang__)
#define BOOSTED_COLD __attribute__((noinline, cold))
#else
#define BOOSTED_COLD
#endif
