#pragma once
/// The rows of `pkm sweep`: one CSV line or one JSON object per step, with the quantities of
/// `pkm eval`. CSV columns are named as the keys of `pkm eval --json`, a matrix M giving
/// columns M[i][j]; a value that is not finite is an empty CSV field and null in JSON.

#include "capability.h"
#include "mechanism.h"
#include "report/numberformat.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace pkm::report {

/// The columns are worked out once, so a CSV row is a loop of writeNumber calls into a
/// reused buffer: no allocation per row.
class SweepRowFormatter
{
public:
    /// `withParameters`: every row starts with all parameters (a parameter sweep). The rows
    /// must use `mechanism`'s report layout.
    SweepRowFormatter(const Mechanism &mechanism, bool withParameters);

    /// Size of the value buffer the rows need: the mechanism's values, then the capability's.
    std::size_t valueCount() const { return static_cast<std::size_t>(m_layout.size + capabilitySize()); }

    /// The CSV header line.
    void csvHeader(std::string &out) const;

    /// Bytes a CSV row may take: every field at its longest.
    std::size_t csvRowBound() const;

    /// Evaluates `pose` into `values` and writes its CSV row at `out` (csvRowBound() bytes of
    /// room); returns the end. The hot loop of a sweep: no std::string; the capability columns
    /// take the pose's Jacobians (Mechanism::jacobians(), a few small allocations) and, in a
    /// parameter sweep, the row's actuators.
    char *csvRow(char *out, const Mechanism &mechanism, const Pose &pose, std::span<double> values) const;

    /// The names of the columns, as csvHeader() gives them.
    std::vector<std::string> columnNames() const;
    /// Index into columnNames() of "singularity", whose numbers numberRow() gives as
    /// SingularityType values (singularityName() names them).
    std::size_t singularityColumn() const;

    /// Evaluates `pose` into `values` and writes the number of column c to row[c·stride], the
    /// value csvRow() prints (display units), NaN where csvRow() leaves the field empty. For
    /// the Python module's sweeps: the same columns and numbers as the CSV, unformatted.
    void numberRow(double *row, std::size_t stride, const Mechanism &mechanism, const Pose &pose,
        std::span<double> values) const;

    /// Evaluates `pose` into `values` and appends its JSON row, the row number `index` of the
    /// sweep (rows after the first are preceded by ",\n").
    void jsonRow(std::string &out, std::int64_t index, const Mechanism &mechanism, const Pose &pose,
        std::span<double> values) const;

private:
    int capabilitySize() const { return m_capabilityLayout ? m_capabilityLayout->size : 0; }
    /// The actuators of `mechanism` when its capability group has the formatter's layout.
    std::optional<capability::Actuators> actuatorsOf(const Mechanism &mechanism) const;
    /// The capability values of `pose` after the mechanism's in `values`; returns the class
    /// they are settled for (capability::deliveryClass()).
    SingularityType evaluateCapability(const Mechanism &mechanism, const Pose &pose, SingularityType type,
        std::span<double> values) const;

    struct Column {
        enum Kind { Value, SingularityType, SingularityMargin } kind;
        int offset; ///< in the value buffer
        Unit unit;
        std::string name;
    };

    const ReportLayout &m_layout;
    capability::Actuators m_actuators; ///< of the formatter's mechanism (re-read for a parameter sweep)
    const ReportLayout *m_capabilityLayout = nullptr;
    bool m_withParameters = false;
    std::vector<const ParameterInfo *> m_parameters;
    std::vector<Column> m_columns;
    /// The text csvRow() last wrote for each value column, and the value it was: a column that
    /// stays the same from row to row (a stroke, a constant stiffness) is copied, not formatted
    /// again. Formatting is most of a CSV sweep's time.
    struct LastText {
        std::uint64_t bits = ~std::uint64_t {0}; ///< a NaN pattern no value column gives
        unsigned char length = 0;
        char text[maxNumberLength];
    };
    mutable std::vector<LastText> m_lastText;
};

} // namespace pkm::report
