#include "text.h"

#include "mechanism.h"

#include <mutex>
#include <shared_mutex>

namespace pkm::text {

namespace {

std::shared_mutex &hooksMutex()
{
    static std::shared_mutex mutex;
    return mutex;
}

Hooks &hooks()
{
    static Hooks current;
    return current;
}

void replaceAll(std::string &text, std::string_view from, std::string_view to)
{
    if (from == to)
        return;
    for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
        text.replace(at, from.size(), to);
}

} // namespace

void install(Hooks newHooks)
{
    std::unique_lock lock(hooksMutex());
    hooks() = std::move(newHooks);
}

Hooks installed()
{
    std::shared_lock lock(hooksMutex());
    return hooks();
}

std::string translate(const char *context, const char *source, const char *disambiguation, int n)
{
    decltype(Hooks::translate) look = nullptr;
    {
        std::shared_lock lock(hooksMutex());
        look = hooks().translate;
    }
    if (look)
        return look(context, source, disambiguation, n);
    std::string text(source);
    if (n >= 0)
        replaceAll(text, "%n", std::to_string(n));
    return text;
}

std::string label(std::string_view source)
{
    if (source.empty())
        return {};
    return translate("core", std::string(source).c_str());
}

std::string format(std::string_view pattern, std::initializer_list<std::string_view> args)
{
    std::string text;
    text.reserve(pattern.size() + 16 * args.size());
    for (std::size_t i = 0; i < pattern.size(); ++i) {
        if (pattern[i] == '%' && i + 1 < pattern.size() && pattern[i + 1] >= '1' && pattern[i + 1] <= '9') {
            const auto index = static_cast<std::size_t>(pattern[i + 1] - '1');
            if (index < args.size()) {
                text.append(*(args.begin() + index));
                ++i;
                continue;
            }
        }
        text.push_back(pattern[i]);
    }
    return text;
}

std::string number(double value, int decimals)
{
    std::string text = formatNumber(value, decimals);
    std::string point, minus;
    {
        std::shared_lock lock(hooksMutex());
        point = hooks().decimalPoint;
        minus = hooks().minusSign;
    }
    if (!point.empty())
        replaceAll(text, ".", point);
    if (!minus.empty() && !text.empty() && text.front() == '-')
        text.replace(0, 1, minus);
    return text;
}

std::string millimetres(double value)
{
    return format(translate("core", "%1 mm"), {number(value, 2)});
}

} // namespace pkm::text
