#include "report/numberformat.h"

#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace pkm::report {

// Why 15 significant digits rather than the shortest round-trip form: 15 (DBL_DIG) is the
// number of digits any decimal keeps through a double, so what a person types comes back
// unchanged — `--set theta=30` prints 30, where the shortest form prints 29.999999999999996
// after the degree → radian → degree conversion. The digits dropped are the last-ulp noise of
// that conversion; JSON, CSV and every run agree digit for digit. Fixed decimals were refused:
// they would cut the significant digits of small quantities (J⁻¹ ≈ 0.009 rad/mm).
//
// Speed: a sweep formats ~18 million numbers; std::to_chars(general, 15) costs ~50 ns each on
// the target machine, which alone would take most of the 1 s budget. The fast path below
// produces the identical text in a fraction of that for all but exact ties and the extremes,
// which it leaves to std::to_chars (tst_cli compares the two on millions of values).

namespace {

constexpr double powersOfTen[] = {1e-4, 1e-3, 1e-2, 1e-1, 1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11,
    1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18};

/// The 8 decimal digits of n < 10^8, one digit value (0–9) per byte, most significant first
/// in memory (little-endian): all 8 digits at once in one register, with no table and no
/// store-then-reload of single bytes.
std::uint64_t digitBytes(std::uint32_t n)
{
    std::uint64_t merged = n / 10000 | static_cast<std::uint64_t>(n % 10000) << 32; // 2 lanes of 4 digits
    const std::uint64_t hundreds = ((merged * 10486) >> 20) & 0x0000007F0000007FULL; // lane / 100
    merged = hundreds | (merged - 100 * hundreds) << 16; // 4 lanes of 2 digits
    const std::uint64_t tens = ((merged * 103) >> 10) & 0x000F000F000F000FULL; // lane / 10
    return tens | (merged - 10 * tens) << 8; // 8 lanes of 1 digit
}

void store(char *out, std::uint64_t bytes)
{
    std::memcpy(out, &bytes, sizeof bytes);
}

/// printf("%.15g") for 1e-4 ≤ |value| < 1e15, where %g uses plain decimal notation. Scales
/// |value| to 15 integer digits by an exact power of ten (one rounding) and rounds to an
/// integer; returns nullptr, leaving the work to std::to_chars, when the fraction is within
/// that rounding error of ½ or the result is near a power of ten. Writes up to 32 bytes
/// (whole 8-byte words past the end of the text; the caller's buffer has room).
char *writeGeneral15Fast(char *out, double value)
{
    if constexpr (std::endian::native != std::endian::little)
        return nullptr;
    const double magnitude = std::abs(value);
    if (!(magnitude >= powersOfTen[0] && magnitude < 1e15))
        return nullptr;
    // floor(log10(magnitude)) from the binary exponent: floor(e2·log10 2) is it or one less.
    // (The inexact 10^-k only matter at the edges, where the range check below catches them.)
    std::uint64_t bits;
    std::memcpy(&bits, &magnitude, sizeof bits);
    const int binaryExponent = static_cast<int>((bits >> 52) & 0x7FF) - 1023;
    int exponent = (binaryExponent * 78913) >> 18; // 78913 / 2^18 ≈ log10 2
    if (magnitude >= powersOfTen[exponent + 5])
        ++exponent;
    const double scaled = magnitude * powersOfTen[14 - exponent + 4]; // 10^0 … 10^18: exact
    if (!(scaled >= 1e14 + 1.0 && scaled < 1e15 - 1.0))
        return nullptr;
    auto digits = static_cast<std::uint64_t>(scaled); // floor
    const double fraction = scaled - static_cast<double>(digits); // exact: scaled < 2^50
    // The product is correctly rounded: off by at most half an ulp of `scaled`. Within that of
    // ½ (one value in ten or so), the product's exact error decides: a product's rounding error
    // is a double, fma gives it exactly, and the sign of (fraction − ½) + error is the sign of
    // the exact sum, so only a true tie is left to std::to_chars.
    const double halfUlp = scaled >= 0x1p49 ? 0x1p-4 : scaled >= 0x1p48 ? 0x1p-5 : scaled >= 0x1p47 ? 0x1p-6 : 0x1p-7;
    const double aboveHalf = fraction - 0.5; // exact
    if (std::abs(aboveHalf) <= halfUlp) {
        const double error = std::fma(magnitude, powersOfTen[14 - exponent + 4], -scaled); // exact
        const double side = aboveHalf + error; // its sign is exact
        if (side == 0.0)
            return nullptr;
        digits += side > 0.0 ? 1 : 0;
    } else {
        digits += aboveHalf > 0.0 ? 1 : 0;
    }

    // The 15 digits d0…d14 in two words: first = d0…d7, second = d8…d14 and a zero byte.
    const std::uint64_t high = digitBytes(static_cast<std::uint32_t>(digits / 100000000)); // 0 d0 … d6
    const std::uint64_t low = digitBytes(static_cast<std::uint32_t>(digits % 100000000)); // d7 … d14
    const std::uint64_t first = high >> 8 | low << 56;
    const std::uint64_t second = low >> 8;
    // The last significant digit (%g drops trailing zeros): the highest non-zero byte.
    const int last = second ? 8 + (63 - std::countl_zero(second)) / 8 : (63 - std::countl_zero(first)) / 8;
    constexpr std::uint64_t ascii = 0x3030303030303030ULL;

    *out = '-';
    out += value < 0 ? 1 : 0;
    if (exponent < 0) {
        store(out, 0x3030303030302E30ULL); // "0.000000": "0." and the zeros 10^exponent needs
        out += 1 - exponent;
        store(out, first + ascii);
        store(out + 8, second + ascii);
        return out + last + 1;
    }
    const int integerDigits = exponent + 1;
    store(out, first + ascii);
    store(out + 8, second + ascii);
    if (last < integerDigits)
        return out + integerDigits;
    // Rewrite the fraction digits one place to the right, behind the decimal point.
    const int shift = 8 * integerDigits;
    const std::uint64_t fraction0
        = integerDigits < 8 ? first >> shift | second << (64 - shift) : second >> (shift - 64);
    const std::uint64_t fraction1 = integerDigits < 8 ? second >> shift : 0;
    store(out + integerDigits + 1, fraction0 + ascii);
    store(out + integerDigits + 9, fraction1 + ascii);
    out[integerDigits] = '.';
    return out + last + 2;
}

} // namespace

char *writeNumber(char *out, double value)
{
    if (value == 0.0)
        value = 0.0; // -0 → 0
    if (char *end = writeGeneral15Fast(out, value))
        return end;
    return std::to_chars(out, out + maxNumberLength, value, std::chars_format::general, 15).ptr;
}

void appendNumber(std::string &out, double value)
{
    char buffer[maxNumberLength];
    out.append(buffer, writeNumber(buffer, value));
}

std::string numberText(double value)
{
    std::string text;
    appendNumber(text, value);
    return text;
}

double cleanCoordinate(double value)
{
    const double rounded = std::round(value * 1e9) / 1e9;
    return rounded == 0.0 ? 0.0 : rounded;
}

} // namespace pkm::report
