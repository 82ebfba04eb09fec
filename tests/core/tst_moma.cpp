// MOMA: filled in by the MOMA test work.
#include "moma.h"

#include <QTest>

class TestMoma : public QObject
{
    Q_OBJECT
private slots:
    void placeholder() { QVERIFY(true); }
};

QTEST_APPLESS_MAIN(TestMoma)
#include "tst_moma.moc"
