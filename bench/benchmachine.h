#pragma once
// What the benchmarks print with their figures: the machine they belong to (issue of a
// figure measured on one class of machine and read as holding on another).
#include "mapclones.h"

#include <fstream>
#include <string>

namespace pkm::bench {

/// "AMD EPYC 7B13 (sse4_2 avx avx2 fma avx512f; maps: AVX2)": the CPU model, its vector
/// extensions and the ones the map loops use (mapclones.h: built without AVX-512, they time
/// a machine with AVX2 alone).
inline std::string cpuText()
{
    std::ifstream info("/proc/cpuinfo");
    std::string line, model, flags;
    while (std::getline(info, line)) {
        if (model.empty() && line.rfind("model name", 0) == 0)
            model = line.substr(line.find(':') + 2);
        if (flags.empty() && line.rfind("flags", 0) == 0)
            flags = line.substr(line.find(':') + 1);
    }
    flags += ' ';
    std::string text = model.empty() ? std::string("unknown CPU") : model;
    text += " (";
    bool first = true;
    for (const char *extension : {"sse4_2", "avx", "avx2", "fma", "avx512f"}) {
        if (flags.find(' ' + std::string(extension) + ' ') == std::string::npos)
            continue;
        if (!first)
            text += ' ';
        text += extension;
        first = false;
    }
    text += "; maps: ";
    text += mapInstructionSet();
    text += ')';
    return text;
}

} // namespace pkm::bench
