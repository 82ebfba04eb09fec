#pragma once
// PKM_MAP_CLONES before a map loop's function builds it for AVX-512 and AVX2 as well as the
// baseline x86-64; the loader picks the best the processor has (GCC function
// multi-versioning), so one binary runs everywhere and a machine with AVX2 but no AVX-512
// still gets 256-bit vectors. Elsewhere (another compiler or processor) it is nothing.
// PKM_MAP_CLONES_NO_AVX512 (CMake: -DPKM_MAP_AVX512=OFF) leaves the AVX-512 version out, so
// that a machine with AVX-512 runs and times what one with AVX2 alone runs.
#if defined(__GNUC__) && defined(__x86_64__) && !defined(__clang__) && defined(PKM_MAP_CLONES_NO_AVX512)
#define PKM_MAP_CLONES [[gnu::target_clones("avx2", "default")]]
#elif defined(__GNUC__) && defined(__x86_64__) && !defined(__clang__)
#define PKM_MAP_CLONES [[gnu::target_clones("avx512f", "avx2", "default")]]
#else
#define PKM_MAP_CLONES
#endif

namespace pkm {
/// What the map loops run with on this processor: "AVX-512", "AVX2" or "x86-64" (the
/// baseline), or "portable" where there are no clones; the benchmarks print it.
const char *mapInstructionSet();
} // namespace pkm
