// Texts that wrap and still fit: a slider's name on no more than two lines at its narrowest
// (WrapLabel; "q₁ (улаз, са погоном)" took three, more than six rows had room for), and a
// column of texts that takes the height its words need where there is room and scrolls where
// there is not (FitScrollArea; the four-bar's class in words was cut mid-sentence at 1024×768);
// and pages that ask for the room of the one in sight only (PageStack: the kinds' panels not
// shown held the side panel wide, and the docks' tabs lost their titles' ends).
#include "fitscrollarea.h"
#include "pagestack.h"
#include "wraplabel.h"

#include <QLabel>
#include <QScrollBar>
#include <QTest>
#include <QVBoxLayout>

using namespace pkm;

class TestTextFit : public QObject
{
    Q_OBJECT

private slots:
    void wrapLabelTakesTwoLinesAtMost()
    {
        WrapLabel label(2);
        label.setText(QStringLiteral("<b>q₁</b> <span style='color:#555'>(улаз, са погоном)</span>"));
        const int oneLine = label.heightForWidth(QWIDGETSIZE_MAX);
        const int twoLines = oneLine + label.fontMetrics().lineSpacing();
        const int least = label.minimumSizeHint().width();
        QVERIFY(label.heightForWidth(least) <= twoLines);
        QVERIFY(label.heightForWidth(least - 1) > twoLines); // the least such width
        // QLabel alone goes down to its longest word, on three lines here
        QLabel plain(label.text());
        plain.setWordWrap(true);
        QVERIFY(plain.minimumSizeHint().width() < least);
        QVERIFY(plain.heightForWidth(plain.minimumSizeHint().width()) > twoLines);
        // not wrapped, it is QLabel's own
        label.setWordWrap(false);
        QCOMPARE(label.minimumSizeHint(), label.QLabel::minimumSizeHint());
    }

    void fitScrollAreaScrollsOnlyWithoutRoom()
    {
        QWidget window;
        auto *layout = new QVBoxLayout(&window);
        auto *content = new QWidget;
        auto *column = new QVBoxLayout(content);
        auto *text = new QLabel(QStringLiteral("Crank-rocker: s + l = AB + AD = 40 + 140 = 180 mm < p + q = BC + CD = "
                                               "100 + 120 = 220 mm; the crank AB, the shortest link, turns all the way "
                                               "round, and the rocker CD swings between 34.0° and 81.4°."),
            content);
        text->setWordWrap(true);
        column->addWidget(text);
        auto *area = new FitScrollArea(content);
        layout->addWidget(area);
        auto *below = new QWidget;
        below->setMinimumHeight(100);
        layout->addWidget(below, 1);
        window.resize(220, 600);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        // room: the whole text, no scroll bar
        QTRY_COMPARE(area->viewport()->height(), content->heightForWidth(area->viewport()->width()));
        QVERIFY(!area->verticalScrollBar()->isVisible());
        QVERIFY(text->height() >= text->heightForWidth(text->width()));
        // little room: the area gives way down to three lines and scrolls the rest
        window.resize(220, 100 + 3 * window.fontMetrics().lineSpacing() + 30);
        QTRY_VERIFY(area->verticalScrollBar()->isVisible());
        QVERIFY(area->height() < content->heightForWidth(area->viewport()->width()));
        QVERIFY(below->height() >= 100);
        QVERIFY(text->height() >= text->heightForWidth(text->width())); // whole, in the scrolled view
        QVERIFY(area->minimumSizeHint().height() <= 3 * area->fontMetrics().lineSpacing());
    }

    void pageStackAsksForThePageInSight()
    {
        PageStack stack;
        auto *narrow = new QWidget;
        narrow->setMinimumSize(100, 50);
        auto *wide = new QWidget;
        wide->setMinimumSize(400, 80);
        stack.addWidget(narrow);
        stack.addWidget(wide);
        QCOMPARE(stack.minimumSizeHint(), QSize(100, 50));
        stack.setCurrentWidget(wide);
        QCOMPARE(stack.minimumSizeHint(), QSize(400, 80));
        QStackedWidget plain; // what QStackedWidget asks for: its largest page, whichever is shown
        plain.addWidget(new QWidget);
        plain.widget(0)->setMinimumSize(100, 50);
        plain.addWidget(new QWidget);
        plain.widget(1)->setMinimumSize(400, 80);
        QCOMPARE(plain.minimumSizeHint().width(), 400);
    }
};

QTEST_MAIN(TestTextFit)
#include "tst_textfit.moc"
