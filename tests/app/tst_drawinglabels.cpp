// The 2D drawing's labels on a projector: in the main window at 1280×720, for every preset at
// its home pose and across the range of each joint variable, no label covers another one, and
// an angle's label that had to move away from its arc is joined to it by a leader. A teacher
// found the П-joint's "μ = 21.8°" over the end of "d = 183.1 mm" and of "a = 170 mm" at θ = 0.
// A joint's or a bar's name pushed away from what it names is joined to it by a leader, and a
// bar's name is nearer its own bar than any other: the five-bar's "E" stood 90 px under its
// joint, and MOMA's S₁ and S₂ stood one over the other between both links. No label is cut by
// the view's edge.
#include "gui/mainwindow.h"

#include "document/document.h"
#include "linkageview.h"
#include "scenelayout.h"
#include "scenepainter.h"
#include "support/app.h"
#include "units.h"

#include <QPolygonF>
#include <QTest>
#include <QTransform>
#include <QUndoStack>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <numbers>

using namespace pkm;
using namespace pkm::test;

namespace {

/// A placed text's knock-out box on screen, turned as it is drawn.
QPolygonF boxOf(const drawing::Text &text)
{
    QTransform turn;
    turn.translate(text.centre.x(), text.centre.y());
    turn.rotate(text.rotationDegrees);
    const QSizeF size = text.box;
    return turn.map(QPolygonF(QRectF(QPointF(-0.5 * size.width(), -0.5 * size.height()), size)));
}

/// The texts of `list` shown on screen.
std::vector<drawing::Text> textsOf(const drawing::DrawList &list)
{
    std::vector<drawing::Text> texts;
    for (const drawing::Primitive &item : list.items) {
        const auto *text = std::get_if<drawing::Text>(&item.shape);
        if (text && drawing::shownOnScreen(item.medium) && !text->box.isEmpty())
            texts.push_back(*text);
    }
    return texts;
}

/// The distance from `point` to the rectangle `box` (0 inside it).
double distanceTo(const QRectF &box, const QPointF &point)
{
    const double dx = std::max({box.left() - point.x(), 0.0, point.x() - box.right()});
    const double dy = std::max({box.top() - point.y(), 0.0, point.y() - box.bottom()});
    return std::hypot(dx, dy);
}

/// The distance from `point` to the segment from `a` to `b`.
double distanceTo(const QPointF &a, const QPointF &b, const QPointF &point)
{
    const QPointF d = b - a;
    const double squared = QPointF::dotProduct(d, d);
    const double t = squared > 0.0 ? std::clamp(QPointF::dotProduct(point - a, d) / squared, 0.0, 1.0) : 0.0;
    return QLineF(point, a + t * d).length();
}

/// "'A' covers 'B'" for each pair of labels that overlap by more than a pixel's sliver.
/// The view's style at presentation mode's text size (150 %).
SceneStyle presentationStyle(const LinkageView &view)
{
    SceneStyle style = view.sceneStyle();
    style.fontPixels *= 1.5;
    style.jointFontPixels *= 1.5;
    return style;
}

/// The screen's layout options in `area`: the labels kept inside it and off the view's ghosts.
drawing::LayoutOptions screenOptions(const LinkageView &view, const ViewMapping &mapping, const QRectF &area)
{
    drawing::LayoutOptions options;
    options.labelRoom = area;
    for (const Scene &ghost : view.ghostScenes()) {
        const std::vector<QLineF> lines = drawing::ghostLines(ghost, mapping);
        options.avoid.insert(options.avoid.end(), lines.begin(), lines.end());
    }
    return options;
}

QStringList coveredLabels(const std::vector<drawing::Text> &texts)
{
    QStringList covered;
    for (std::size_t i = 0; i < texts.size(); ++i) {
        for (std::size_t j = i + 1; j < texts.size(); ++j) {
            const QPolygonF common = boxOf(texts[i]).intersected(boxOf(texts[j]));
            if (common.boundingRect().width() > 1.5 && common.boundingRect().height() > 1.5)
                covered << QStringLiteral("'%1' covers '%2'").arg(texts[i].text, texts[j].text);
        }
    }
    return covered;
}

} // namespace

class TestDrawingLabels : public QObject
{
    Q_OBJECT

private:
    std::unique_ptr<MainWindow> m_window;

    /// The view's scene laid out as the view lays it out: labels inside its rectangle.
    drawing::DrawList laidOutAsShown() const
    {
        const LinkageView *view = m_window->linkageView();
        drawing::LayoutOptions options;
        options.labelRoom = QRectF(view->rect()).adjusted(2.0, 2.0, -2.0, -2.0);
        return drawing::layoutScene(view->scene(), view->mapping(), view->sceneStyle(), options);
    }

    /// `preset` opened and fitted (Home), laid out as the view shows it.
    drawing::DrawList openedAndFitted(const QString &preset)
    {
        if (!m_window->openDesign(preset))
            return {};
        QTest::keyClick(m_window->linkageView(), Qt::Key_Home);
        return laidOutAsShown();
    }

    QStringList coveredHere(const QString &where)
    {
        LinkageView *view = m_window->linkageView();
        const drawing::DrawList list = laidOutAsShown();
        QStringList covered = coveredLabels(textsOf(list));
        // none cut by the view's edge (the П-joint's "d = 148.2 mm" at θ = −30° was)
        for (const drawing::Text &text : textsOf(list)) {
            const QRectF box = boxOf(text).boundingRect();
            const QRectF room(view->rect());
            // a point far out (the four-bar's instant centre P) has its name out there too
            const bool far = !box.intersects(room.adjusted(-box.width(), -box.height(), box.width(), box.height()));
            if (!far && !room.adjusted(-0.5, -0.5, 0.5, 0.5).contains(box))
                covered << QStringLiteral("'%1' cut by the view's edge (%2, %3)").arg(text.text).arg(box.left()).arg(box.top());
        }
        // no angle's leader runs under a dimension's or another angle's text (the П-joint's θ
        // leader under "a = 170 mm" left a stray tick beside it); a name may cover a little of
        // one rather than leave its joint
        std::vector<drawing::Text> texts;
        for (const drawing::Primitive &item : list.items) {
            const auto *text = std::get_if<drawing::Text>(&item.shape);
            if (text && item.layer == drawing::Layer::Dimensions && drawing::shownOnScreen(item.medium) && !text->box.isEmpty())
                texts.push_back(*text);
        }
        for (const drawing::Primitive &item : list.items) {
            const auto *lines = std::get_if<drawing::Lines>(&item.shape);
            if (!lines || lines->pen.colour != view->sceneStyle().angle || lines->pen.dash != drawing::Dash::Solid)
                continue;
            for (const QLineF &leader : lines->lines) {
                for (const drawing::Text &text : texts) {
                    const QPolygonF box = boxOf(text);
                    if (box.boundingRect().adjusted(-1.5, -1.5, 1.5, 1.5).contains(leader.p2()))
                        continue; // its own label
                    for (int k = 2; k <= 18; ++k) { // past the arc's end, short of the label
                        if (box.containsPoint(leader.pointAt(k / 20.0), Qt::OddEvenFill)) {
                            covered << QStringLiteral("a leader runs under '%1'").arg(text.text);
                            break;
                        }
                    }
                }
            }
        }
        for (QString &line : covered)
            line.prepend(where + QStringLiteral(": "));
        return covered;
    }

private slots:
    void initTestCase()
    {
        m_window.reset(freshMainWindow(QSize(1280, 720)));
        QVERIFY(m_window);
    }

    void labelsDoNotCoverEachOther_data() { addEveryPresetRows(); }

    /// At the home pose and at nine poses across each variable's range, after Fit.
    void labelsDoNotCoverEachOther()
    {
        PKM_FETCH_PRESET(preset);
        QVERIFY(m_window->openDesign(preset));
        QTest::keyClick(m_window->linkageView(), Qt::Key_Home);
        QStringList covered = coveredHere(QStringLiteral("home"));
        Document *document = m_window->document();
        const int variables = int(document->mechanism()->variableInfo().size());
        int poses = 1;
        for (int v = 0; v < variables; ++v) {
            const Interval range = document->mechanism()->variableRange(v);
            if (!std::isfinite(range.min) || !std::isfinite(range.max))
                continue;
            for (int k = 1; k <= 9; ++k) {
                const double value = range.min + (range.max - range.min) * k / 10.0;
                if (!document->setVariable(v, value))
                    continue;
                ++poses;
                covered << coveredHere(QStringLiteral("%1 = %2").arg(v).arg(value));
            }
            QVERIFY(m_window->openDesign(preset)); // the next variable from the home pose again
        }
        QVERIFY2(covered.isEmpty(), qPrintable(QStringLiteral("%1 overlaps in %2 poses:\n").arg(covered.size()).arg(poses)
            + covered.join(QLatin1Char('\n'))));
    }

    void namesStayWithWhatTheyName_data() { addEveryPresetRows(); }

    /// At 1280×720 after Fit, each joint's name is next to its joint or has a leader from the
    /// joint's ring to its edge; each bar's name is nearer its bar than any other bar, and one
    /// set off from its bar has a leader too.
    void namesStayWithWhatTheyName()
    {
        PKM_FETCH_PRESET(preset);
        QVERIFY(m_window->openDesign(preset));
        LinkageView *view = m_window->linkageView();
        QTest::keyClick(view, Qt::Key_Home);
        const Scene &scene = view->scene();
        const SceneStyle &style = view->sceneStyle();
        const drawing::DrawList list = drawing::layoutScene(scene, view->mapping(), style);
        std::vector<QLineF> leaders;
        for (const drawing::Primitive &item : list.items) {
            const auto *lines = std::get_if<drawing::Lines>(&item.shape);
            if (lines && item.layer == drawing::Layer::Text)
                leaders.insert(leaders.end(), lines->lines.begin(), lines->lines.end());
        }
        const auto device = [&](int joint) {
            return view->mapping().toDevice(Eigen::Vector2d(scene.joints[std::size_t(joint)].position.head<2>()));
        };
        const auto joinedBy = [&](const QRectF &box, const auto &fromWhat) {
            return std::any_of(leaders.begin(), leaders.end(), [&](const QLineF &leader) {
                return fromWhat(leader.p1()) && distanceTo(box.adjusted(-1.5, -1.5, 1.5, 1.5), leader.p2()) == 0.0;
            });
        };
        const double px = style.pixelSize;
        QStringList astray;
        int names = 0;
        for (const drawing::Text &text : textsOf(list)) {
            const QRectF box = boxOf(text).boundingRect();
            for (int j = 0; j < int(scene.joints.size()); ++j) {
                if (!text.font.bold() || QString::fromStdString(scene.joints[std::size_t(j)].label) != text.text)
                    continue;
                ++names;
                const QPointF at = device(j);
                const double ring = (style.pivotRadius + 2.0) * px;
                const bool next = distanceTo(box, at) <= (style.pivotRadius + 24.0) * px;
                if (!next && !joinedBy(box, [&](const QPointF &p) { return QLineF(p, at).length() <= ring; }))
                    astray << QStringLiteral("joint %1: %2 px from it, no leader").arg(text.text).arg(distanceTo(box, at));
            }
            // the bar it names: of those so named (the O-X glide's two links l), the nearest
            const SceneBar *bar = nullptr;
            double own = 1e300;
            for (const SceneBar &candidate : scene.bars) {
                const double there = distanceTo(device(candidate.from), device(candidate.to), box.center());
                if (!text.font.bold() && text.rotationDegrees == 0.0 && QString::fromStdString(candidate.label) == text.text
                    && there < own) {
                    bar = &candidate;
                    own = there;
                }
            }
            if (!bar)
                continue;
            ++names;
            const QPointF a = device(bar->from), b = device(bar->to);
            for (const SceneBar &other : scene.bars) {
                const double there = distanceTo(device(other.from), device(other.to), box.center());
                if (other.label != bar->label && there < own)
                    astray << QStringLiteral("bar %1: nearer %2 (%3 px) than its own (%4 px)")
                                  .arg(text.text, QString::fromStdString(other.label)).arg(there).arg(own);
            }
            // the gap between the bar's axis and the name's box: a bar's half width and a few px
            double gap = 1e300;
            for (int k = 0; k <= 64; ++k)
                gap = std::min(gap, distanceTo(box, a + (b - a) * (k / 64.0)));
            if (gap > 16.0 * px && !joinedBy(box, [&](const QPointF &p) { return distanceTo(a, b, p) <= 8.0 * px; }))
                astray << QStringLiteral("bar %1: %2 px from it, no leader").arg(text.text).arg(gap);
        }
        QCOMPARE_GT(names, 0);
        QVERIFY2(astray.isEmpty(), qPrintable(astray.join(QLatin1Char('\n'))));
    }

    /// The 5R from two R̲RR legs named A₁ and A₂ between its legs, over the other modes'
    /// dashes, where they read as the space's between the bars: a base joint's name stands on
    /// the outer side of its joint, as the five-bar's A does.
    void baseNamesStandOutside()
    {
        for (const QString &preset : {QStringLiteral("pp-5r"), QStringLiteral("fivebar-example")}) {
            const drawing::DrawList list = openedAndFitted(preset);
            QVERIFY(!list.items.empty());
            const LinkageView *view = m_window->linkageView();
            const Scene &scene = view->scene();
            QPointF middle;
            int named = 0;
            std::map<QString, QPointF> joints;
            for (const SceneJoint &joint : scene.joints) {
                if (joint.label.empty())
                    continue;
                const QPointF at = view->mapping().toDevice(Eigen::Vector2d(joint.position.head<2>()));
                joints[QString::fromStdString(joint.label)] = at;
                middle += at;
                ++named;
            }
            middle /= double(named);
            int checked = 0;
            for (const drawing::Text &text : textsOf(list)) {
                if (!text.font.bold() || !QStringList {QStringLiteral("A₁"), QStringLiteral("A₂"), QStringLiteral("A")}.contains(text.text))
                    continue;
                const QPointF joint = joints.at(text.text), outward = joint - middle, name = text.centre - joint;
                QVERIFY2(QPointF::dotProduct(outward, name) > 0.0,
                         qPrintable(QStringLiteral("%1: %2 inside the linkage").arg(preset, text.text)));
                ++checked;
            }
            QCOMPARE(checked, preset == QStringLiteral("pp-5r") ? 2 : 1);
        }
    }

    /// The O-X glide's top rail named "D · 0" inside the triangle of its two links, where it
    /// names neither: a rail's name goes past the rail's end before it goes among the links.
    void railNameStaysOutOfTheTriangle()
    {
        const drawing::DrawList list = openedAndFitted(QStringLiteral("oxglide-prototype"));
        QVERIFY(!list.items.empty());
        const LinkageView *view = m_window->linkageView();
        const Scene &scene = view->scene();
        std::vector<QLineF> links;
        for (const SceneBar &bar : scene.bars) {
            if (bar.label == "l")
                links.emplace_back(view->mapping().toDevice(Eigen::Vector2d(scene.joints[std::size_t(bar.from)].position.head<2>())),
                                   view->mapping().toDevice(Eigen::Vector2d(scene.joints[std::size_t(bar.to)].position.head<2>())));
        }
        QCOMPARE(links.size(), std::size_t(2));
        int rails = 0;
        for (const drawing::Text &text : textsOf(list)) {
            if (!text.text.contains(QStringLiteral(" · ")))
                continue;
            ++rails;
            // where a horizontal line through the name crosses each link
            std::vector<double> across;
            for (const QLineF &link : links) {
                const double t = (text.centre.y() - link.y1()) / (link.y2() - link.y1());
                if (t >= 0.0 && t <= 1.0)
                    across.push_back(link.x1() + t * (link.x2() - link.x1()));
            }
            const bool between = across.size() == 2 && text.centre.x() > std::min(across[0], across[1])
                && text.centre.x() < std::max(across[0], across[1]);
            QVERIFY2(!between, qPrintable(QStringLiteral("'%1' between the links").arg(text.text)));
        }
        QCOMPARE(rails, 4);
    }

    /// The П-joint in its small view at θ = 0: "d = 183.1 mm" along the diagonal lay over bar
    /// OC, the parallelogram being narrower than the text. It now stands upright outside with
    /// a leader to the diagonal, and covers neither crank; a CAD drawing keeps it on its line.
    void diagonalTextCoversNoBar()
    {
        QVERIFY(m_window->openDesign(QStringLiteral("pjoint-prototype")));
        LinkageView *view = m_window->linkageView();
        QTest::keyClick(view, Qt::Key_Home);
        const Scene &scene = view->scene();
        const drawing::DrawList list = drawing::layoutScene(scene, view->mapping(), view->sceneStyle());
        const auto device = [&](int joint) {
            return view->mapping().toDevice(Eigen::Vector2d(scene.joints[std::size_t(joint)].position.head<2>()));
        };
        const QPointF O = device(0), B = device(1), A = device(2), C = device(3);
        const std::vector<drawing::Text> texts = textsOf(list);
        const auto d = std::find_if(texts.begin(), texts.end(), [](const drawing::Text &t) { return t.text.startsWith(u"d = "); });
        QVERIFY(d != texts.end());
        const QPolygonF box = boxOf(*d);
        const double half = 0.5 * view->sceneStyle().barWidth * view->sceneStyle().pixelSize;
        for (const auto &[from, to] : {std::pair {O, C}, std::pair {B, A}}) {
            const QPointF across = QLineF(from, to).normalVector().unitVector().p2() - from;
            for (int k = 0; k <= 32; ++k) {
                for (double side : {-half, 0.0, half}) { // the bar's axis and its edges
                    const QPointF at = from + (to - from) * (k / 32.0) + side * across;
                    QVERIFY2(!box.containsPoint(at, Qt::OddEvenFill),
                        qPrintable(QStringLiteral("'%1' covers a crank at (%2, %3)").arg(d->text).arg(at.x()).arg(at.y())));
                }
            }
        }
        if (d->rotationDegrees == 0.0) { // moved off the diagonal: a leader joins them
            const QRectF edge = box.boundingRect().adjusted(-1.5, -1.5, 1.5, 1.5);
            bool joined = false;
            for (const drawing::Primitive &item : list.items) {
                const auto *lines = std::get_if<drawing::Lines>(&item.shape);
                for (std::size_t k = 0; lines && k < lines->lines.size(); ++k) {
                    const QLineF &line = lines->lines[k];
                    joined = joined || (distanceTo(O, A, line.p1()) < 12.0 && edge.contains(line.p2()));
                }
            }
            QVERIFY(joined);
            // the CAD drawing writes it along the diagonal
            int onLine = 0;
            for (const drawing::Primitive &item : list.items) {
                const auto *text = std::get_if<drawing::Text>(&item.shape);
                if (text && item.medium == drawing::Medium::Cad && text->text == d->text && text->rotationDegrees != 0.0)
                    ++onLine;
            }
            QCOMPARE(onLine, 1);
        }
    }

    /// The four-bar's coupler curve ran through the B, M and δ labels: a label now stands off
    /// it where the view has room, at the home pose and across the crank's turn (eight labels
    /// on it in these five poses before). M, which traces it, has its name beside it.
    void couplerCurveCrossesNoLabel()
    {
        QVERIFY(m_window->openDesign(QStringLiteral("fourbar-example")));
        LinkageView *view = m_window->linkageView();
        QTest::keyClick(view, Qt::Key_Home);
        QStringList crossed;
        for (double alpha : {60.0, 0.0, 120.0, 200.0, 300.0}) {
            QVERIFY(m_window->document()->setVariable(0, alpha * std::numbers::pi / 180.0));
            const Scene &scene = view->scene();
            QVERIFY(!scene.polylines.empty());
            const drawing::DrawList list = drawing::layoutScene(scene, view->mapping(), view->sceneStyle());
            // the name of the point that traces the curve (M) stands next to it, on it or not
            QStringList tracers;
            for (const SceneJoint &joint : scene.joints) {
                for (const ScenePolyline &path : scene.polylines) {
                    for (const Eigen::Vector3d &p : path.points) {
                        if ((p - joint.position).head<2>().norm() < 0.5 && !tracers.contains(QString::fromStdString(joint.label)))
                            tracers << QString::fromStdString(joint.label);
                    }
                }
            }
            for (const drawing::Text &text : textsOf(list)) {
                if (tracers.contains(text.text))
                    continue;
                const QPolygonF box = boxOf(text);
                int inside = 0;
                for (const ScenePolyline &path : scene.polylines) {
                    for (const Eigen::Vector3d &p : path.points)
                        inside += box.containsPoint(view->mapping().toDevice(Eigen::Vector2d(p.head<2>())), Qt::OddEvenFill);
                }
                if (inside > 0)
                    crossed << QStringLiteral("α = %1°: '%2'").arg(alpha).arg(text.text);
            }
        }
        QVERIFY2(crossed.isEmpty(), qPrintable(crossed.join(QLatin1Char('\n'))));
    }

    /// The П-joint at θ = 0: μ is measured at A between the diagonal and the crank, a narrow
    /// angle inside the parallelogram that the diagonal's length fills. Its label goes where it
    /// covers no other, with a leader to its arc.
    /// A ground pivot is named beside its symbol, on the outer side, where its angle label
    /// would take the place outward: at presentation mode's text size the five-bar's "E" went
    /// inside the linkage among the other assembly mode's dashes.
    void aGroundPivotIsNamedBesideItsSymbol()
    {
        QVERIFY(m_window->openDesign(QStringLiteral("fivebar-example")));
        LinkageView *view = m_window->linkageView();
        const SceneStyle style = presentationStyle(*view);
        const Scene &scene = view->scene();
        const QRectF area(0, 0, 770, 380);
        const ViewMapping mapping = LinkageView::screenMapping(scene, scene.poseExtent, area, style);
        const std::vector<drawing::Text> texts = textsOf(drawing::layoutScene(scene, mapping, style));
        const auto named = [&](const char *name) {
            const auto text = std::find_if(texts.begin(), texts.end(), [&](const drawing::Text &t) { return t.text == QLatin1String(name); });
            return text == texts.end() ? QPointF(qQNaN(), qQNaN()) : boxOf(*text).boundingRect().center();
        };
        const auto at = [&](const char *name) {
            for (const SceneJoint &joint : scene.joints) {
                if (joint.label == name)
                    return mapping.toDevice(Eigen::Vector2d(joint.position.head<2>()));
            }
            return QPointF(qQNaN(), qQNaN());
        };
        // E, the right-hand pivot: its name right of it and not above it; A's left of A
        const QPointF E = at("E"), nameE = named("E"), A = at("A"), nameA = named("A");
        QVERIFY2(nameE.x() > E.x() && nameE.y() >= E.y(),
                 qPrintable(QStringLiteral("E at %1, %2, its name at %3, %4").arg(E.x()).arg(E.y()).arg(nameE.x()).arg(nameE.y())));
        QVERIFY2(nameA.x() < A.x() && nameA.y() >= A.y(),
                 qPrintable(QStringLiteral("A at %1, %2, its name at %3, %4").arg(A.x()).arg(A.y()).arg(nameA.x()).arg(nameA.y())));
    }

    /// On screen the labels keep off the other modes' ghosts drawn under the linkage: MOMA
    /// 3a's R₁ and R₂ had stood on the dashes of its other assembly mode.
    void labelsKeepOffTheGhosts()
    {
        QVERIFY(m_window->openDesign(QStringLiteral("moma-3a")));
        LinkageView *view = m_window->linkageView();
        QVERIFY(!view->ghostScenes().isEmpty());
        const SceneStyle style = presentationStyle(*view);
        const Scene &scene = view->scene();
        const QRectF area(0, 0, 760, 410);
        const ViewMapping mapping = LinkageView::screenMapping(scene, scene.poseExtent, area, style);
        const drawing::LayoutOptions options = screenOptions(*view, mapping, area);
        QVERIFY(!options.avoid.empty());
        const std::vector<drawing::Text> texts = textsOf(drawing::layoutScene(scene, mapping, style, options));
        QStringList crossed;
        for (const drawing::Text &text : texts) {
            const QRectF box = boxOf(text).boundingRect();
            for (const QLineF &line : options.avoid) {
                // the line sampled along its length: where it runs through the label's box
                for (int k = 1; k < 40; ++k) {
                    if (box.contains(line.pointAt(k / 40.0))) {
                        crossed << text.text;
                        break;
                    }
                }
            }
        }
        QVERIFY2(crossed.isEmpty(), qPrintable(crossed.join(QStringLiteral(", "))));
    }

    /// Keeping off the ghosts never costs a name: among the 3-RP̲R's five ghosts its struts'
    /// names q₁ and q₃ were left out in some assembly modes, every place beside them crossing
    /// a ghost's dashes.
    void namesStayAmongTheGhosts()
    {
        QVERIFY(m_window->openDesign(QStringLiteral("pp-3rpr")));
        LinkageView *view = m_window->linkageView();
        Document *document = m_window->document();
        const SceneStyle style = presentationStyle(*view);
        const QRectF area(0, 0, 760, 410);
        const int alternatives = int(document->modeAlternatives().size());
        QCOMPARE(alternatives, 5);
        for (int k = -1; k < alternatives; ++k) {
            if (k >= 0) // each other mode in turn, from the preset's
                QVERIFY(document->switchMode(document->modeAlternatives()[std::size_t(k)]).ok());
            const Scene &scene = view->scene();
            const ViewMapping mapping = LinkageView::screenMapping(scene, scene.poseExtent, area, style);
            const drawing::LayoutOptions options = screenOptions(*view, mapping, area);
            QStringList shown;
            for (const drawing::Text &text : textsOf(drawing::layoutScene(scene, mapping, style, options)))
                shown << text.text;
            for (const char *name : {"q₁", "q₂", "q₃"})
                QVERIFY2(shown.contains(QString::fromUtf8(name)), qPrintable(QStringLiteral("mode %1: %2").arg(k).arg(shown.join(u' '))));
            if (k >= 0)
                document->undoStack()->undo();
        }
    }

    /// An angle's leader does not run under a bar's name: the five-bar's "AE", placed after
    /// θ₁ and its leader, sat on the leader in presentation mode as Play turned θ₁.
    void barNamesKeepOffTheLeaders()
    {
        QVERIFY(m_window->openDesign(QStringLiteral("fivebar-example")));
        LinkageView *view = m_window->linkageView();
        const SceneStyle style = presentationStyle(*view);
        const QRectF area(0, 0, 760, 410);
        QStringList crossed;
        for (double degrees = 60.0; degrees <= 150.0; degrees += 2.0) {
            if (!m_window->document()->setVariable(0, degrees * units::degree).ok())
                continue;
            const Scene &scene = view->scene();
            const ViewMapping mapping = LinkageView::screenMapping(scene, scene.poseExtent, area, style);
            const drawing::DrawList list = drawing::layoutScene(scene, mapping, style, screenOptions(*view, mapping, area));
            for (const drawing::Primitive &item : list.items) {
                const auto *lines = std::get_if<drawing::Lines>(&item.shape);
                if (!lines || lines->pen.colour != style.angle || lines->pen.dash != drawing::Dash::Solid)
                    continue;
                for (const QLineF &leader : lines->lines) {
                    for (const drawing::Text &text : textsOf(list)) {
                        const QPolygonF box = boxOf(text);
                        const bool bar = text.text.size() == 2 && text.text.at(0).isUpper() && text.text.at(1).isUpper();
                        for (int k = 2; bar && k <= 18; ++k) {
                            if (box.containsPoint(leader.pointAt(k / 20.0), Qt::OddEvenFill)) {
                                crossed << QStringLiteral("θ₁ = %1°: under '%2'").arg(degrees).arg(text.text);
                                break;
                            }
                        }
                    }
                }
            }
        }
        QVERIFY2(crossed.isEmpty(), qPrintable(crossed.join(QStringLiteral(", "))));
    }

    /// The scale bar is drawn over the linkage: a label keeps out of its box (the five-bar's
    /// E, named right of its pivot, went under the bar's white box once the pose came near).
    void labelsKeepOutOfTheScaleBar()
    {
        QVERIFY(m_window->openDesign(QStringLiteral("fivebar-example")));
        LinkageView *view = m_window->linkageView();
        const SceneStyle style = view->sceneStyle();
        const Scene &scene = view->scene();
        const QRectF area(0, 0, 760, 410);
        ViewMapping mapping = LinkageView::screenMapping(scene, scene.poseExtent, area, style);
        const QRectF bar = ScenePainter::scaleBarBox(area, mapping, style, nullptr);
        QVERIFY(!bar.isEmpty());
        const auto joint = std::find_if(scene.joints.begin(), scene.joints.end(), [](const SceneJoint &j) { return j.label == "E"; });
        QVERIFY(joint != scene.joints.end());
        const QPointF E = mapping.toDevice(Eigen::Vector2d(joint->position.head<2>()));
        // E 40 px left of the bar's box and 20 px above it: E's name and θ₄ went under it
        mapping.origin += QPointF(bar.left() - 40.0, bar.top() - 20.0) - E;
        drawing::LayoutOptions options;
        options.labelRoom = area;
        options.covered.push_back(bar);
        for (const drawing::Text &text : textsOf(drawing::layoutScene(scene, mapping, style, options)))
            QVERIFY2(!boxOf(text).boundingRect().intersects(bar), qPrintable(text.text));
    }

    void narrowAngleGetsALeader()
    {
        QVERIFY(m_window->openDesign(QStringLiteral("pjoint-prototype")));
        QTest::keyClick(m_window->linkageView(), Qt::Key_Home);
        LinkageView *view = m_window->linkageView();
        const drawing::DrawList list = drawing::layoutScene(view->scene(), view->mapping(), view->sceneStyle());
        const std::vector<drawing::Text> texts = textsOf(list);
        QVERIFY2(coveredLabels(texts).isEmpty(), qPrintable(coveredLabels(texts).join(QLatin1Char('\n'))));
        const auto mu = std::find_if(texts.begin(), texts.end(), [](const drawing::Text &t) {
            return t.text.startsWith(QStringLiteral("μ"));
        });
        QVERIFY(mu != texts.end());
        const QRectF label = boxOf(*mu).boundingRect();
        const QPointF A = view->mapping().toDevice(Eigen::Vector2d(view->scene().joints[2].position.head<2>()));
        int leaders = 0;
        for (const drawing::Primitive &item : list.items) {
            const auto *lines = std::get_if<drawing::Lines>(&item.shape);
            if (!lines || lines->pen.colour != view->sceneStyle().angle || lines->pen.dash != drawing::Dash::Solid)
                continue;
            for (const QLineF &line : lines->lines) {
                // from near A (on μ's arc) to the edge of μ's label
                const bool fromArc = QLineF(line.p1(), A).length() < 60.0;
                const bool toLabel = label.adjusted(-1.5, -1.5, 1.5, 1.5).contains(line.p2());
                leaders += fromArc && toLabel ? 1 : 0;
            }
        }
        const bool nextToArc = QLineF(label.center(), A).length() < 0.5 * label.width() + 40.0;
        QVERIFY2(leaders == 1 || nextToArc, qPrintable(QStringLiteral("μ's label at %1, %2 from A (%3, %4), %5 leaders")
            .arg(label.center().x()).arg(label.center().y()).arg(A.x()).arg(A.y()).arg(leaders)));
    }
};

QTEST_MAIN(TestDrawingLabels)
#include "tst_drawinglabels.moc"
