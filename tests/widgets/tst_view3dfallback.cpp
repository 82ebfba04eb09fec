// The 3D view where OpenGL cannot start (the offscreen platform with no X display): no crash,
// a clear message instead of the picture, refused pictures with the reason, and a camera that
// still follows the mouse, the wheel, the keys and the panel's buttons.

#include "linkageview3d.h"
#include "registry.h"

#include <QApplication>
#include <QDir>
#include <QFile>
#include <QLabel>
#include <QMouseEvent>
#include <QTemporaryDir>
#include <QTest>
#include <QToolButton>
#include <QWheelEvent>

#include <cmath>

using namespace pkm;
using Projection = Camera3D::Projection;

namespace {

void sendMouse(QWidget *w, QEvent::Type type, const QPoint &p, Qt::MouseButton button, Qt::MouseButtons buttons)
{
    QMouseEvent event(type, QPointF(p), w->mapToGlobal(QPointF(p)), button, buttons, Qt::NoModifier);
    QApplication::sendEvent(w, &event);
}

} // namespace

class TestView3DFallback : public QObject
{
    Q_OBJECT

private slots:
    void viewWithoutOpenGl();
};

void TestView3DFallback::viewWithoutOpenGl()
{
    // main() took the display away: no OpenGL here.
    View3DPanel panel;
    LinkageView3D *view = panel.view();
    const Result<MechanismPtr> pjoint = createMechanism("pjoint", {});
    QVERIFY(pjoint.ok());
    view->setScene((*pjoint)->scene3d((*pjoint)->homePose()));
    panel.resize(500, 400);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    QTest::qWait(50);
    QVERIFY(!view->isGlAvailable());
    QVERIFY(!view->hasGlSurface()); // no OpenGL window where OpenGL cannot start
    QVERIFY(view->glStatus().startsWith(QStringLiteral("3D view unavailable: OpenGL 3.3 could not be started")));
    const auto labels = view->findChildren<QLabel *>();
    QCOMPARE(labels.size(), 1);
    QVERIFY(labels.front()->isVisible());
    QCOMPARE(labels.front()->text().simplified(), view->glStatus());
    QCOMPARE(labels.front()->geometry(), view->rect());
    // The message is what the user sees: dark text on the light background, where the picture goes.
    const QImage shown = view->grab().toImage();
    QDir().mkpath(QDir::temp().filePath(QStringLiteral("pkm-view3d")));
    shown.save(QDir::temp().filePath(QStringLiteral("pkm-view3d/unavailable.png")));
    int text = 0;
    for (int y = 0; y < shown.height(); ++y)
        for (int x = 0; x < shown.width(); ++x)
            text += qGray(shown.pixel(x, y)) < 100 ? 1 : 0;
    QVERIFY(text > 200);
    QCOMPARE(shown.pixelColor(2, 2), Renderer3D::backgroundColour());
    QVERIFY(view->renderImage(QSize(300, 200)).isNull());
    QCOMPARE(view->imageError(), view->glStatus());
    QTemporaryDir directory;
    QString error;
    const QString path = directory.filePath(QStringLiteral("view.png"));
    QVERIFY(!panel.savePicture(path, &error));
    QVERIFY(error.contains(QStringLiteral("OpenGL 3.3")));
    QVERIFY(!QFile::exists(path));

    // The camera still follows the mouse and the keys (it is maths, not GL).
    const double yaw = view->camera().yaw();
    sendMouse(view, QEvent::MouseButtonPress, {100, 100}, Qt::LeftButton, Qt::LeftButton);
    sendMouse(view, QEvent::MouseMove, {160, 90}, Qt::NoButton, Qt::LeftButton);
    sendMouse(view, QEvent::MouseButtonRelease, {160, 90}, Qt::LeftButton, Qt::NoButton);
    QVERIFY(view->camera().yaw() != yaw);
    const Eigen::Vector3d target = view->camera().target();
    sendMouse(view, QEvent::MouseButtonPress, {100, 100}, Qt::RightButton, Qt::RightButton);
    sendMouse(view, QEvent::MouseMove, {130, 120}, Qt::NoButton, Qt::RightButton);
    sendMouse(view, QEvent::MouseButtonRelease, {130, 120}, Qt::RightButton, Qt::NoButton);
    const Eigen::Vector3d panned = view->camera().target();
    QVERIFY((panned - target).norm() > 1e-6);
    const Eigen::Vector3d direction = view->camera().viewDirection();
    sendMouse(view, QEvent::MouseButtonDblClick, {100, 100}, Qt::LeftButton, Qt::LeftButton);
    sendMouse(view, QEvent::MouseButtonRelease, {100, 100}, Qt::LeftButton, Qt::NoButton);
    // fitted again (the model's outline centred, so the pan is undone), the new direction kept
    const Eigen::Vector3d fitted = view->camera().target();
    QVERIFY((fitted - panned).norm() > 1e-6);
    QVERIFY((view->camera().viewDirection() - direction).norm() < 1e-12);
    sendMouse(view, QEvent::MouseButtonDblClick, {100, 100}, Qt::LeftButton, Qt::LeftButton);
    sendMouse(view, QEvent::MouseButtonRelease, {100, 100}, Qt::LeftButton, Qt::NoButton);
    QVERIFY((view->camera().target() - fitted).norm() < 1e-9); // the same fit again
    const double before = view->camera().distance();
    QWheelEvent wheel(QPointF(50, 60), view->mapToGlobal(QPointF(50, 60)), QPoint(), QPoint(0, 240), Qt::NoButton,
        Qt::NoModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(view, &wheel);
    QVERIFY(std::abs(view->camera().distance() - before / (Camera3D::zoomStep * Camera3D::zoomStep)) < 1e-9 * before);
    QTest::keyClick(view, Qt::Key_7);
    QVERIFY((view->camera().viewDirection() - Eigen::Vector3d(0, -1, 0)).norm() < 1e-12);
    QTest::keyClick(view, Qt::Key_5);
    QCOMPARE(view->projection(), Projection::Orthographic);
    auto *perspective = panel.findChild<QToolButton *>(QStringLiteral("perspective"));
    QVERIFY(perspective && !perspective->isChecked());
    perspective->click();
    QCOMPARE(view->projection(), Projection::Perspective);
    panel.findChild<QToolButton *>(QStringLiteral("front"))->click();
    QVERIFY((view->camera().viewDirection() - Eigen::Vector3d(0, 0, -1)).norm() < 1e-12);
}

int main(int argc, char **argv)
{
    // Deterministically without OpenGL: the offscreen platform, and no X display it could use.
    qunsetenv("DISPLAY");
    qunsetenv("WAYLAND_DISPLAY");
    qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication application(argc, argv);
    TestView3DFallback test;
    return QTest::qExec(&test, argc, argv);
}

#include "tst_view3dfallback.moc"
