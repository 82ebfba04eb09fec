#include "clisweep.h"

#include "clireport.h"
#include "jsonwriter.h"
#include "numberformat.h"
#include "sweeprowformatter.h"

#include <QString>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <condition_variable>
#include <cstring>
#include <functional>
#include <mutex>
#include <string_view>
#include <thread>

namespace pkm::cli {

namespace {

/// Rows per chunk: big enough that a chunk is one large fwrite (≈ 1 MB of CSV), small enough
/// that two chunks per thread in flight stay a few MB.
constexpr std::int64_t chunkRows = 4096;

/// "75°", "500 mm", "0.4": a value in display units with its unit, for messages.
std::string withUnit(double displayValue, const Unit &unit)
{
    std::string text = numberText(displayValue);
    if (!unit.symbol.empty()) {
        if (unit.symbol != "°")
            text += ' ';
        text += unit.symbol;
    }
    return text;
}

bool writeAll(std::FILE *out, std::string_view text)
{
    return std::fwrite(text.data(), 1, text.size(), out) == text.size();
}

/// The text of one chunk of rows: `bytes` keeps its size between chunks (CSV rows are written
/// through a pointer into it), `length` is how much of it is text.
struct ChunkText {
    std::string bytes;
    std::size_t length = 0;
    std::string_view view() const { return {bytes.data(), length}; }
};

/// Formats chunks 0 … chunks − 1 with `format` on worker threads and writes them in order on
/// the calling thread. `format` returning false stops everything: NotDeterministic.
Sweep::Outcome writeChunks(
    std::int64_t chunks, const std::function<bool(std::int64_t, ChunkText &)> &format, std::FILE *out)
{
    const unsigned threads = std::clamp(std::thread::hardware_concurrency(), 1u, 8u);
    if (chunks < 2 || threads < 2) {
        ChunkText text;
        for (std::int64_t chunk = 0; chunk < chunks; ++chunk) {
            if (!format(chunk, text))
                return Sweep::Outcome::NotDeterministic;
            if (!writeAll(out, text.view()))
                return Sweep::Outcome::OutputError;
        }
        return Sweep::Outcome::Written;
    }

    // A ring of 2 buffers per thread: chunk c goes to slot c % slotCount once chunk c − slotCount has
    // been written, which bounds the memory whatever K is.
    const auto slotCount = static_cast<std::int64_t>(2 * threads);
    std::vector<ChunkText> texts(static_cast<std::size_t>(slotCount));
    std::vector<std::int64_t> ready(static_cast<std::size_t>(slotCount), -1);
    std::mutex mutex;
    std::condition_variable changed;
    std::int64_t written = 0;
    bool stop = false;
    bool failed = false;
    std::atomic<std::int64_t> next {0};

    const auto work = [&] {
        for (;;) {
            const std::int64_t chunk = next.fetch_add(1);
            if (chunk >= chunks)
                return;
            const auto slot = static_cast<std::size_t>(chunk % slotCount);
            {
                std::unique_lock lock(mutex);
                changed.wait(lock, [&] { return stop || written > chunk - slotCount; });
                if (stop)
                    return;
            }
            const bool ok = format(chunk, texts[slot]);
            {
                std::lock_guard lock(mutex);
                failed = failed || !ok;
                stop = stop || !ok;
                ready[slot] = chunk;
            }
            changed.notify_all();
        }
    };
    std::vector<std::thread> workers;
    for (unsigned t = 0; t < threads; ++t)
        workers.emplace_back(work);

    bool writeOk = true;
    for (std::int64_t chunk = 0; chunk < chunks; ++chunk) {
        const auto slot = static_cast<std::size_t>(chunk % slotCount);
        {
            std::unique_lock lock(mutex);
            changed.wait(lock, [&] { return stop || ready[slot] == chunk; });
            if (stop)
                break;
        }
        if (!writeAll(out, texts[slot].view())) {
            writeOk = false;
            break;
        }
        {
            std::lock_guard lock(mutex);
            written = chunk + 1;
        }
        changed.notify_all();
    }
    {
        std::lock_guard lock(mutex);
        stop = true;
    }
    changed.notify_all();
    for (std::thread &worker : workers)
        worker.join();
    if (failed)
        return Sweep::Outcome::NotDeterministic;
    return writeOk ? Sweep::Outcome::Written : Sweep::Outcome::OutputError;
}

} // namespace

Result<Sweep> Sweep::solve(const PreparedDesign &design, const Invocation &invocation)
{
    const Mechanism &mechanism = *design.mechanism;
    Sweep sweep(design);
    sweep.m_var = *invocation.var;
    sweep.m_from = *invocation.from;
    sweep.m_to = *invocation.to;
    sweep.m_steps = *invocation.steps;
    sweep.m_json = invocation.json;
    sweep.m_variable = mechanism.variableIndex(sweep.m_var);
    if (sweep.m_variable >= 0)
        sweep.m_unit = mechanism.variableInfo()[static_cast<std::size_t>(sweep.m_variable)].unit;
    else if ((sweep.m_parameter = findParameter(mechanism, sweep.m_var)))
        sweep.m_unit = sweep.m_parameter->unit;
    else
        return unknownSetName(mechanism, "--var " + sweep.m_var, sweep.m_var, design.origin);

    // Solve every step before printing anything, so a failure leaves stdout empty. The pose at
    // the start of each chunk is kept: the formatting pass then runs the chunks in parallel,
    // independently, and gives exactly the rows a serial loop would.
    sweep.m_chunkStarts.reserve(static_cast<std::size_t>((sweep.m_steps + chunkRows - 1) / chunkRows));
    Pose near = design.pose;
    Step step;
    for (std::int64_t i = 0; i < sweep.m_steps; ++i) {
        if (i % chunkRows == 0)
            sweep.m_chunkStarts.push_back(near);
        if (const auto failure = sweep.solveStep(i, near, step)) {
            const std::string context = "sweep step " + std::to_string(i + 1) + " of " + std::to_string(sweep.m_steps)
                + " (" + sweep.m_var + " = " + withUnit(sweep.valueAt(i), sweep.m_unit) + ")";
            return inContext(*failure, context);
        }
        near = step.pose;
    }
    return sweep;
}

double Sweep::valueAt(std::int64_t i) const
{
    if (i == 0 || m_steps == 1)
        return m_from;
    if (i == m_steps - 1)
        return m_to;
    return m_from + (m_to - m_from) * (static_cast<double>(i) / static_cast<double>(m_steps - 1));
}

std::optional<Failure> Sweep::solveStep(std::int64_t i, const Pose &near, Step &step) const
{
    const double value = valueAt(i);
    if (!m_parameter) {
        auto solved = m_design->mechanism->solveWith(near, m_variable, m_unit.fromDisplay(value));
        if (!solved)
            return solved.failure();
        step.mechanism = m_design->mechanism.get();
        step.pose = *solved;
        return std::nullopt;
    }
    auto changed = designfile::setDisplayParameter(m_design->mechanism, QString::fromStdString(m_var), value);
    if (!changed)
        return changed.failure();
    const Mechanism &mechanism = **changed;
    auto solved = m_design->poseSets.empty() ? mechanism.solveInverse(m_design->pose.outputs, &near)
                                             : solvePoseSets(mechanism, near, m_design->poseSets);
    if (!solved)
        return solved.failure();
    step.owner = *changed;
    step.mechanism = step.owner.get();
    step.pose = *solved;
    return std::nullopt;
}

void Sweep::jsonHeader(std::string &out) const
{
    const Mechanism &mechanism = *m_design->mechanism;
    JsonWriter json(out, JsonWriter::Style::Pretty);
    json.beginObject();
    json.key("mechanism").string(mechanism.kind());
    writeParametersJson(json, mechanism, true);
    json.key("sweep");
    json.beginObject(true);
    json.key("var").string(m_var);
    json.key("group").string(m_parameter ? "parameters" : "pose");
    json.key("unit").string(m_unit.symbol);
    json.key("from").number(m_from);
    json.key("to").number(m_to);
    json.key("steps").integer(m_steps);
    json.endObject();
    json.key("rows");
    out += "[\n"; // the rows follow, one per line
}

Sweep::Outcome Sweep::write(std::FILE *out) const
{
    const SweepRowFormatter formatter(*m_design->mechanism, m_parameter != nullptr);
    std::string text;
    if (m_json)
        jsonHeader(text);
    else
        formatter.csvHeader(text);
    if (!writeAll(out, text))
        return Outcome::OutputError;

    const auto formatChunk = [&](std::int64_t chunk, ChunkText &chunkText) {
        const std::int64_t begin = chunk * chunkRows;
        const std::int64_t end = std::min(m_steps, begin + chunkRows);
        std::string &bytes = chunkText.bytes;
        if (m_json)
            bytes.clear();
        else if (const auto room = static_cast<std::size_t>(end - begin) * formatter.csvRowBound(); bytes.size() < room)
            bytes.resize(room); // CSV rows are written straight into a buffer for the longest possible rows
        char *cursor = bytes.data();
        std::vector<double> values(formatter.valueCount());
        Pose near = m_chunkStarts[static_cast<std::size_t>(chunk)];
        Step step;
        for (std::int64_t i = begin; i < end; ++i) {
            if (solveStep(i, near, step).has_value())
                return false; // solve() solved it: the mechanism is not deterministic
            if (m_json)
                formatter.jsonRow(bytes, i, *step.mechanism, step.pose, values);
            else
                cursor = formatter.csvRow(cursor, *step.mechanism, step.pose, values);
            near = step.pose;
        }
        chunkText.length = m_json ? bytes.size() : static_cast<std::size_t>(cursor - bytes.data());
        return true;
    };
    const Outcome rows = writeChunks(static_cast<std::int64_t>(m_chunkStarts.size()), formatChunk, out);
    if (rows != Outcome::Written)
        return rows;
    return writeAll(out, m_json ? "\n]\n}\n" : "") ? Outcome::Written : Outcome::OutputError;
}

} // namespace pkm::cli
