// The 2D drawing's labels on a projector: in the main window at 1280×720, for every preset at
// its home pose and across the range of each joint variable, no label covers another one, and
// an angle's label that had to move away from its arc is joined to it by a leader. A teacher
// found the П-joint's "μ = 21.8°" over the end of "d = 183.1 mm" and of "a = 170 mm" at θ = 0.
#include "gui/mainwindow.h"

#include "document/document.h"
#include "linkageview.h"
#include "scenelayout.h"
#include "support/app.h"

#include <QPolygonF>
#include <QTest>
#include <QTransform>

#include <memory>

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

/// "'A' covers 'B'" for each pair of labels that overlap by more than a pixel's sliver.
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

    QStringList coveredHere(const QString &where)
    {
        LinkageView *view = m_window->linkageView();
        const drawing::DrawList list = drawing::layoutScene(view->scene(), view->mapping(), view->sceneStyle());
        QStringList covered = coveredLabels(textsOf(list));
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

    /// The П-joint at θ = 0: μ is measured at A between the diagonal and the crank, a narrow
    /// angle inside the parallelogram that the diagonal's length fills. Its label goes where it
    /// covers no other, with a leader to its arc.
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
