#pragma once
/// One table per mechanism kind declares its design parameters: each row is a ParameterInfo
/// together with the design field it reads and writes. Everything a kind used to write out by
/// hand, name by name, comes from that one table: the lookup (parameterInfo()), the values
/// (parameters()), and the validated change (withParameters(), withParameter(), createFrom()).
/// A parameter is then named, described and wired to its field in one place, so the three can
/// no longer disagree.
///
/// A change is validated in three steps, the first failure is the answer:
///  1. each given value: its name is known, its value lies in the domain (Mechanism::checkDomain)
///     and passes the row's rule (a mode that must be exactly +1 or −1);
///  2. a derived parameter is not given with the stored one it writes (k with b);
///  3. the stored values are written first and the derived ones after them, so that the order
///     of the changes does not matter (k = b/a given with a sizes b from the new a).
/// The kind's create() then checks the design as a whole (a stroke order, a loop that closes).

#include "mechanism.h"
#include "text.h"

#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

namespace pkm {

/// How one parameter reads and writes a design: plain functions, so a table is made once and
/// shared by every design of the kind.
template <class Design>
struct FieldAccess {
    double (*get)(const Design &) = nullptr;
    void (*set)(Design &, double) = nullptr;
};

/// The order in which changes given together are checked (step 1 above): each kind keeps the
/// order its messages always had, since the first failure is the one reported.
enum class CheckOrder {
    /// Change by change, in name order: the name, then the domain, then the rule.
    EachChange,
    /// Every known change against its domain (name order), then every rule (table order), then
    /// the names.
    DomainsFirst,
};

/// What differs between kinds in validating a change.
struct ChangeRules {
    /// "The five-bar linkage has no parameter named '%1'.", marked QT_TRANSLATE_NOOP("core", …).
    const char *unknownName = "";
    CheckOrder order = CheckOrder::EachChange;
    /// createFrom() checks each given value (step 1) before making the design; false: only the
    /// design as a whole is checked (by create()), and names it does not know are ignored.
    bool checkGiven = true;
    /// withParameters() of a single change names that change when a check across parameters
    /// fails (Mechanism::blameChange); false: the kind blames in its own withParameter().
    bool blameSingle = true;
};

/// The rule of a mode that is a sign, exactly −1 or +1 (MOMA's β₁, β₂ and σ, a leg's working
/// mode): any other number is refused with the parameter's name.
inline Result<double> signRule(const ParameterInfo &info, double value)
{
    if (value != 1.0 && value != -1.0) {
        return Failure{FailureKind::InvalidParameter, info.name,
                       text::format(text::translate("core", "%1 = %2 is invalid: it must be -1 or +1."),
                                    {info.name, text::number(value)})};
    }
    return value;
}

template <class Design>
struct ParameterRow {
    ParameterInfo info;
    FieldAccess<Design> field;
    /// A check beyond the domain, with the kind's message (a mode that is exactly ±1); or null.
    Result<double> (*rule)(const ParameterInfo &info, double value) = nullptr;
    /// A derived parameter (info.stored false) writes this stored one ("b" for k = b/a); given
    /// both, the change is refused with clash(derived value, stored value).
    const char *writes = nullptr;
    Failure (*clash)(double value, double storedValue) = nullptr;
};

template <class Design>
class ParameterTable
{
public:
    using Row = ParameterRow<Design>;

    ParameterTable(ChangeRules rules, std::vector<Row> rows)
        : m_rules(rules)
        , m_rows(std::move(rows))
    {
        m_infos.reserve(m_rows.size());
        for (const Row &row : m_rows)
            m_infos.push_back(row.info);
    }

    /// The rows' infos in table order: Mechanism::parameterInfo().
    const std::vector<ParameterInfo> &infos() const { return m_infos; }
    const std::vector<Row> &rows() const { return m_rows; }
    const ChangeRules &rules() const { return m_rules; }

    /// Every parameter's value in `design`, stored and derived: Mechanism::parameters().
    ParameterSet values(const Design &design) const
    {
        ParameterSet values;
        for (const Row &row : m_rows)
            values.emplace(row.info.name, row.field.get(design));
        return values;
    }

    /// `design` with `changes` applied (steps 1–3; step 1 only when `checkEach`), or why not.
    Result<Design> apply(Design design, const ParameterSet &changes, bool checkEach) const
    {
        if (checkEach) {
            if (auto checked = checkChanges(changes); !checked)
                return checked.failure();
        }
        for (const Row &row : m_rows) {
            if (!row.writes)
                continue;
            const auto mine = changes.find(row.info.name), theirs = changes.find(row.writes);
            if (mine != changes.end() && theirs != changes.end())
                return row.clash(mine->second, theirs->second);
        }
        for (const bool stored : {true, false}) {
            for (const Row &row : m_rows) {
                const auto it = changes.find(row.info.name);
                if (row.info.stored == stored && it != changes.end())
                    row.field.set(design, it->second);
            }
        }
        return design;
    }

    /// Row by row, the design's value against its domain and then its rule: for create().
    Result<bool> checkDesign(const Design &design) const
    {
        for (const Row &row : m_rows) {
            const double value = row.field.get(design);
            if (auto checked = Mechanism::checkDomain(row.info, value); !checked)
                return checked.failure();
            if (auto ruled = checkRule(row, value); !ruled)
                return ruled.failure();
        }
        return true;
    }
    /// Only the domains, row by row (a kind whose create() checks its modes after them).
    Result<bool> checkDomains(const Design &design) const
    {
        for (const Row &row : m_rows) {
            if (auto checked = Mechanism::checkDomain(row.info, row.field.get(design)); !checked)
                return checked.failure();
        }
        return true;
    }
    /// Only the rules, row by row.
    Result<bool> checkRules(const Design &design) const
    {
        for (const Row &row : m_rows) {
            if (auto ruled = checkRule(row, row.field.get(design)); !ruled)
                return ruled.failure();
        }
        return true;
    }

    // -- fields ---------------------------------------------------------------------------
    // A locator is a lambda without captures, [](auto &d) -> auto & { return d.alpha[0]; },
    // that finds the field in a design (const or not); the member forms take a plain member.

    /// A real-valued field, read and written as it is.
    template <class Locate>
    static FieldAccess<Design> real(Locate)
    {
        static_assert(std::is_empty_v<Locate>, "a locator captures nothing");
        return {[](const Design &d) { return double(Locate{}(d)); }, [](Design &d, double v) { Locate{}(d) = v; }};
    }
    template <double Design::*Member>
    static FieldAccess<Design> real()
    {
        return real([](auto &d) -> auto & { return d.*Member; });
    }

    /// A ±1 mode kept as an int: a positive value writes +1, any other −1.
    template <class Locate>
    static FieldAccess<Design> sign(Locate)
    {
        static_assert(std::is_empty_v<Locate>, "a locator captures nothing");
        return {[](const Design &d) { return double(Locate{}(d)); },
                [](Design &d, double v) { Locate{}(d) = v > 0 ? 1 : -1; }};
    }
    template <int Design::*Member>
    static FieldAccess<Design> sign()
    {
        return sign([](auto &d) -> auto & { return d.*Member; });
    }

    /// A switch kept as a bool: read as 1 or 0, written on above one half.
    template <bool Design::*Member>
    static FieldAccess<Design> flag()
    {
        return {[](const Design &d) { return d.*Member ? 1.0 : 0.0; }, [](Design &d, double v) { d.*Member = v > 0.5; }};
    }

private:
    const Row *find(std::string_view name) const
    {
        for (const Row &row : m_rows) {
            if (row.info.name == name)
                return &row;
        }
        return nullptr;
    }

    static Result<double> checkRule(const Row &row, double value)
    {
        return row.rule ? row.rule(row.info, value) : Result<double>(value);
    }

    Failure unknown(const std::string &name) const
    {
        return Failure{FailureKind::UnknownName, name,
                       text::format(text::label(m_rules.unknownName), {name})};
    }

    /// Step 1 in the kind's order.
    Result<bool> checkChanges(const ParameterSet &changes) const
    {
        if (m_rules.order == CheckOrder::EachChange) {
            for (const auto &[name, value] : changes) {
                const Row *row = find(name);
                if (!row)
                    return unknown(name);
                if (auto checked = Mechanism::checkDomain(row->info, value); !checked)
                    return checked.failure();
                if (auto ruled = checkRule(*row, value); !ruled)
                    return ruled.failure();
            }
            return true;
        }
        for (const auto &[name, value] : changes) {
            if (const Row *row = find(name)) {
                if (auto checked = Mechanism::checkDomain(row->info, value); !checked)
                    return checked.failure();
            }
        }
        for (const Row &row : m_rows) {
            const auto it = changes.find(row.info.name);
            if (it == changes.end())
                continue;
            if (auto ruled = checkRule(row, it->second); !ruled)
                return ruled.failure();
        }
        for (const auto &[name, value] : changes) {
            if (!find(name))
                return unknown(name);
        }
        return true;
    }

    ChangeRules m_rules;
    std::vector<Row> m_rows;
    std::vector<ParameterInfo> m_infos;
};

/// The parameter half of Mechanism, written once from Kind's table: Kind (the final class)
/// provides `static const ParameterTable<Design> &table()`, `static Result<MechanismPtr>
/// create(const Design &)` (which validates the design as a whole) and `const Design &design()`.
template <class Kind, class Design>
class TabledMechanism : public Mechanism
{
public:
    /// A design from named values; missing ones take Design{}'s.
    static Result<MechanismPtr> createFrom(const ParameterSet &parameters)
    {
        const ParameterTable<Design> &table = Kind::table();
        auto design = table.apply(Design{}, parameters, table.rules().checkGiven);
        if (!design)
            return design.failure();
        return Kind::create(*design);
    }

    const std::vector<ParameterInfo> &parameterInfo() const override { return Kind::table().infos(); }
    ParameterSet parameters() const override { return Kind::table().values(self().design()); }

    Result<MechanismPtr> withParameters(const ParameterSet &changes) const override
    {
        const ParameterTable<Design> &table = Kind::table();
        auto design = table.apply(self().design(), changes, true);
        if (!design)
            return design.failure();
        auto made = Kind::create(*design);
        return table.rules().blameSingle ? blameChange(std::move(made), changes) : made;
    }

    Result<MechanismPtr> withParameter(std::string_view name, double value) const override
    {
        return withParameters({{std::string(name), value}});
    }

private:
    const Kind &self() const { return static_cast<const Kind &>(*this); }
};

} // namespace pkm
