// Rows of a grid two to a line where their box is wide enough, one to a line where it is not,
// and the box asking only for the narrower (the four-bar's link lengths in Russian asked for
// 473 px two to a line, more than a 1024×768 projector leaves).
#include "gridreflow.h"

#include <QGridLayout>
#include <QGroupBox>
#include <QLabel>
#include <QLineEdit>
#include <QSlider>
#include <QTest>

using namespace pkm;

class TestGridReflow : public QObject
{
    Q_OBJECT

private slots:
    void twoToALineWhereTheyFit()
    {
        QGroupBox box(QStringLiteral("Длины звеньев"));
        auto *grid = new QGridLayout(&box);
        std::vector<std::vector<QWidget *>> rows;
        for (const char *name : {"AB кривошип", "BC шатун", "CD коромысло", "AD стойка"}) {
            auto *field = new QLineEdit(&box);
            field->setMinimumWidth(80);
            rows.push_back({new QLabel(QString::fromUtf8(name), &box), new QSlider(Qt::Horizontal, &box), field});
        }
        QWidget *first = rows[0][0], *second = rows[1][0];
        auto *reflow = new GridReflow(&box, grid, rows, 1, 18);
        const int least = box.minimumWidth();
        box.resize(2 * least + 60, 200);
        box.show();
        QVERIFY(QTest::qWaitForWindowExposed(&box));
        QTRY_COMPARE(reflow->perLine(), 2);
        QTRY_COMPARE(second->y(), first->y()); // BC beside AB
        box.resize(least, 300);
        QTRY_COMPARE(reflow->perLine(), 1);
        QTRY_VERIFY(second->y() > first->y()); // BC under AB
        // asking for no more than one to a line needs, whichever is shown
        QCOMPARE(box.minimumWidth(), least);
        QVERIFY(box.minimumSizeHint().width() <= least);
    }
};

QTEST_MAIN(TestGridReflow)
#include "tst_gridreflow.moc"
