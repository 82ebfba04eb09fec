// The generic parameter table (core/parametertable.h) on a kind made up for the test: a box
// with a stored width and height, a derived ratio = height/width that sizes the height, a ±1
// side and an on/off lid. What every real kind relies on is checked here once, apart from any
// kinematics: the lookup, the values, the validated change and its order independence.
#include "parametertable.h"

#include <QTest>

#include <array>
#include <iterator>
#include <limits>

using namespace pkm;

namespace {

struct BoxDesign {
    double width = 10.0;
    double height = 5.0;
    std::array<double, 2> corner = {0.0, 0.0};
    int side = +1;
    bool lid = false;
};

Result<double> sideRule(const ParameterInfo &info, double value)
{
    if (value != 1.0 && value != -1.0)
        return Failure{FailureKind::InvalidParameter, info.name, info.name + " must be +1 or -1."};
    return value;
}

Failure ratioClash(double ratio, double height)
{
    return Failure{FailureKind::InvalidParameter, "ratio",
                   "ratio " + formatNumber(ratio) + " and height " + formatNumber(height) + " both size the box."};
}

/// The box: its parameters are the subject; the rest of the Mechanism interface is the least
/// that compiles (a pose of one input and one output, an empty scene).
class Box final : public TabledMechanism<Box, BoxDesign>
{
public:
    static Result<MechanismPtr> create(const BoxDesign &design)
    {
        if (auto checked = table().checkDesign(design); !checked)
            return checked.failure();
        // a check across parameters, to see who is blamed for it
        if (!(design.height < 4.0 * design.width))
            return Failure{FailureKind::InvalidParameter, "width", "The box is too tall for its width."};
        return MechanismPtr(new Box(design));
    }

    static const ParameterTable<BoxDesign> &table()
    {
        using T = ParameterTable<BoxDesign>;
        using D = BoxDesign;
        static const T table = [] {
            const Interval positive{0.0, 1e5};
            const Interval sign{-1.0, 1.0};
            using G = ParameterGroup;
            const FieldAccess<D> ratio{[](const D &d) { return d.height / d.width; },
                                       [](D &d, double r) { d.height = r * d.width; }};
            const ChangeRules rules{.unknownName = "The box has no parameter named '%1'."};
            return T(rules, {
                {{"width", "w", "width", units::millimetre, G::Geometry, positive, true, false, true, 2, 1}, T::real<&D::width>()},
                {{"height", "h", "height", units::millimetre, G::Geometry, positive, true, false, true, 2, 1}, T::real<&D::height>()},
                {{"ratio", "r", "ratio h/w", units::none, G::Geometry, positive, true, false, false, 3, 0.1}, ratio, nullptr, "height", &ratioClash},
                {{"corner_x", "x", "corner, x", units::millimetre, G::Geometry, Interval{-1e5, 1e5}, false, false, true, 2, 1},
                 T::real([](auto &d) -> auto & { return d.corner[0]; })},
                {{"side", "s", "side", units::none, G::Mode, sign, false, false, true, 0, 2, {{"left", 1.0}, {"right", -1.0}}},
                 T::sign<&D::side>(), &sideRule},
                {{"lid", "l", "lid (1: on)", units::none, G::Mode, Interval{0.0, 1.0}, false, false, true, 0, 1}, T::flag<&D::lid>()},
            });
        }();
        return table;
    }

    const BoxDesign &design() const { return m_design; }

    std::string_view kind() const override { return "box"; }
    const std::vector<VariableInfo> &variableInfo() const override
    {
        static const std::vector<VariableInfo> infos = {{"q", "q", "input", units::none, true, 2},
                                                        {"x", "x", "output", units::none, false, 2}};
        return infos;
    }
    Interval variableRange(int) const override { return {0.0, 1.0}; }
    Pose homePose() const override { return {}; }
    Result<Pose> solveDirect(const Coordinates &, const Pose * = nullptr) const override { return Pose{}; }
    Result<Pose> solveInverse(const Coordinates &, const Pose * = nullptr) const override { return Pose{}; }
    const ReportLayout &reportLayout() const override
    {
        static const ReportLayout layout;
        return layout;
    }
    Singularity evaluate(const Pose &, std::span<double>) const override { return {}; }
    Jacobians jacobians(const Pose &) const override { return {}; }
    KinematicChain kinematicChain(const Pose &) const override { return {}; }
    Scene scene(const Pose &) const override { return {}; }
    Result<Pose> dragHandle(const Pose &current, int, const Eigen::Vector2d &) const override { return current; }

private:
    explicit Box(const BoxDesign &design) : m_design(design) {}

    BoxDesign m_design;
};

const BoxDesign &designOf(const Result<MechanismPtr> &made)
{
    return static_cast<const Box &>(**made).design();
}

} // namespace

class TestParameterTable : public QObject
{
    Q_OBJECT

private slots:
    void lookupFollowsTheTable()
    {
        auto box = Box::createFrom({});
        QVERIFY(box.ok());
        const auto &infos = (*box)->parameterInfo();
        QCOMPARE(infos.size(), std::size_t(6));
        const char *order[] = {"width", "height", "ratio", "corner_x", "side", "lid"};
        for (std::size_t i = 0; i < infos.size(); ++i)
            QCOMPARE(infos[i].name, std::string(order[i]));
        QCOMPARE(&infos, &Box::table().infos()); // one table for every design of the kind
        const ParameterInfo *ratio = (*box)->findParameter("ratio");
        QVERIFY(ratio && !ratio->stored);
        QCOMPARE(ratio->decimals, 3);
        QCOMPARE((*box)->findParameter("side")->choices.size(), std::size_t(2));
        QVERIFY(!(*box)->findParameter("depth"));
    }

    void parametersReadTheFields()
    {
        BoxDesign d;
        d.corner = {-3.5, 0.0};
        d.side = -1;
        d.lid = true;
        auto box = Box::create(d);
        QVERIFY(box.ok());
        const ParameterSet values = (*box)->parameters();
        QCOMPARE(values.size(), std::size_t(6));
        QCOMPARE(values.at("width"), 10.0);
        QCOMPARE(values.at("height"), 5.0);
        QCOMPARE(values.at("ratio"), 0.5); // derived: height/width
        QCOMPARE(values.at("corner_x"), -3.5);
        QCOMPARE(values.at("side"), -1.0);
        QCOMPARE(values.at("lid"), 1.0);
        QCOMPARE(Box::table().values(d), values);
    }

    void changeWritesTheFields()
    {
        auto box = Box::createFrom({});
        auto changed = (*box)->withParameters({{"width", 20.0}, {"corner_x", 7.0}, {"side", -1.0}, {"lid", 1.0}});
        QVERIFY(changed.ok());
        const BoxDesign &d = designOf(changed);
        QCOMPARE(d.width, 20.0);
        QCOMPARE(d.height, 5.0);
        QCOMPARE(d.corner[0], 7.0);
        QCOMPARE(d.side, -1);
        QVERIFY(d.lid);
        // the old design is a value: unchanged
        QCOMPARE(designOf(box).width, 10.0);
        // createFrom starts from the design's defaults
        auto made = Box::createFrom({{"height", 8.0}});
        QVERIFY(made.ok());
        QCOMPARE(designOf(made).height, 8.0);
        QCOMPARE(designOf(made).width, 10.0);
    }

    void derivedParameterIsWrittenLast()
    {
        auto box = Box::createFrom({});
        // ratio sizes the height from the new width, whichever comes first in the set
        for (const ParameterSet &changes : {ParameterSet{{"ratio", 2.0}, {"width", 3.0}},
                                            ParameterSet{{"width", 3.0}, {"ratio", 2.0}}}) {
            auto changed = (*box)->withParameters(changes);
            QVERIFY(changed.ok());
            QCOMPARE(designOf(changed).height, 6.0);
            QCOMPARE((*changed)->parameters().at("ratio"), 2.0);
        }
        auto alone = (*box)->withParameter("ratio", 1.5);
        QVERIFY(alone.ok());
        QCOMPARE(designOf(alone).height, 15.0);
        // the derived one with the stored one it writes: refused, in the kind's words
        auto both = (*box)->withParameters({{"ratio", 2.0}, {"height", 4.0}});
        QVERIFY(!both.ok());
        QCOMPARE(both.failure().culprit, std::string("ratio"));
        QCOMPARE(both.failure().message, std::string("ratio 2 and height 4 both size the box."));
    }

    void refusedValueNamesTheParameter()
    {
        auto box = Box::createFrom({});
        auto negative = (*box)->withParameter("width", -1.0);
        QVERIFY(!negative.ok());
        QCOMPARE(negative.failure().kind, FailureKind::InvalidParameter);
        QCOMPARE(negative.failure().culprit, std::string("width"));
        // the message is Mechanism::checkDomain's, word for word
        QCOMPARE(negative.failure().message,
                 Mechanism::checkDomain(*(*box)->findParameter("width"), -1.0).failure().message);
        auto notANumber = (*box)->withParameter("ratio", std::numeric_limits<double>::quiet_NaN());
        QCOMPARE(notANumber.failure().culprit, std::string("ratio"));
        // a value inside the domain that the row's rule refuses
        auto half = (*box)->withParameter("side", 0.5);
        QCOMPARE(half.failure().culprit, std::string("side"));
        QCOMPARE(half.failure().message, std::string("side must be +1 or -1."));
        auto unknown = (*box)->withParameter("depth", 1.0);
        QCOMPARE(unknown.failure().kind, FailureKind::UnknownName);
        QCOMPARE(unknown.failure().message, std::string("The box has no parameter named 'depth'."));
        // a check across parameters blames the single change that broke it
        auto tall = (*box)->withParameter("height", 100.0);
        QCOMPARE(tall.failure().culprit, std::string("height"));
        QCOMPARE(tall.failure().message, std::string("The box is too tall for its width."));
        // …but not one of several
        auto tallAndWide = (*box)->withParameters({{"height", 100.0}, {"width", 20.0}});
        QCOMPARE(tallAndWide.failure().culprit, std::string("width"));
    }

    void orderOfChangesDoesNotMatter()
    {
        auto box = Box::createFrom({});
        // a tall box is valid only once the wider width is in: given together, in any order
        auto together = (*box)->withParameters({{"height", 100.0}, {"width", 30.0}});
        QVERIFY(together.ok());
        QCOMPARE(designOf(together).height, 100.0);
        // of several bad values, the first in name order is reported, however they were given
        ParameterSet forwards, backwards;
        const std::pair<const char *, double> bad[] = {{"width", -1.0}, {"side", 0.5}, {"height", -2.0}};
        for (const auto &[name, value] : bad)
            forwards[name] = value;
        for (auto it = std::rbegin(bad); it != std::rend(bad); ++it)
            backwards[it->first] = it->second;
        QCOMPARE((*box)->withParameters(forwards).failure().culprit, std::string("height"));
        QCOMPARE((*box)->withParameters(backwards).failure().culprit, std::string("height"));
    }

    void designCheckRowByRow()
    {
        const ParameterTable<BoxDesign> &table = Box::table();
        BoxDesign d;
        d.side = 0; // inside the domain [-1, 1], refused by the rule
        QCOMPARE(table.checkDomains(d).ok(), true);
        QCOMPARE(table.checkRules(d).failure().culprit, std::string("side"));
        QCOMPARE(table.checkDesign(d).failure().culprit, std::string("side"));
        d.width = 0.0; // the domain, in an earlier row, comes first
        QCOMPARE(table.checkDesign(d).failure().culprit, std::string("width"));
        QCOMPARE(Box::create(d).failure().culprit, std::string("width"));
    }
};

QTEST_GUILESS_MAIN(TestParameterTable)
#include "tst_parametertable.moc"
