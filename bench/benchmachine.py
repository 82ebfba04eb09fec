"""The machine a Python benchmark ran on, for its report: the CPU model, the vector extensions
that decide which code paths run (AVX2 and FMA; AVX-512 where present) and the number of
cores, as bench/benchmachine.h prints it for the C++ benchmarks."""

import os


def machine():
    """"AMD EPYC … (sse4_2 avx avx2 fma), 2 cores"; "unknown CPU" without /proc/cpuinfo."""
    model, flags = "unknown CPU", set()
    try:
        with open("/proc/cpuinfo", encoding="utf-8", errors="replace") as info:
            for line in info:
                key, _, value = line.partition(":")
                if key.strip() == "model name" and model == "unknown CPU":
                    model = value.strip()
                elif key.strip() == "flags" and not flags:
                    flags = set(value.split())
    except OSError:
        pass
    extensions = [e for e in ("sse4_2", "avx", "avx2", "fma", "avx512f") if e in flags]
    return f"{model} ({' '.join(extensions)}), {os.cpu_count()} cores"
