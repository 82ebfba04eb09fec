#pragma once
// PKM_MAP_CLONES before a map loop's function builds it for AVX-512 and AVX2 as well as the
// baseline x86-64; the loader picks the best the processor has (GCC function
// multi-versioning), so one binary runs everywhere and a machine with AVX2 but no AVX-512
// still gets 256-bit vectors. Elsewhere (another compiler or processor) it is nothing.
#if defined(__GNUC__) && defined(__x86_64__) && !defined(__clang__)
#define PKM_MAP_CLONES [[gnu::target_clones("avx512f", "avx2", "default")]]
#else
#define PKM_MAP_CLONES
#endif
