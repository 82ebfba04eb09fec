// The 3D view with a real OpenGL 3.3 context (ctest runs it under Xvfb with Mesa's llvmpipe): every
// kind against reference PNGs, a pose change, pictures larger than the widget, its own frames (one
// sample in motion on the CPU, four at rest), an empty scene, "Save picture…" with and without the
// names and a frame's time during a drag. PKM_UPDATE_REFERENCE_IMAGES=1 writes the references to
// tests/widgets/data/; every run leaves its pictures in <temp>/pkm-view3d/ to look at.

#include "linkageview3d.h"
#include "mesh3d.h"
#include "registry.h"
#include "support/kinematics.h"

#include <QDir>
#include <QElapsedTimer>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <map>
#include <memory>
#include <vector>

Q_DECLARE_METATYPE(pkm::Camera3D::Projection)
Q_DECLARE_METATYPE(pkm::Camera3D::StandardView)

using namespace pkm;
using namespace pkm::test;
using Projection = Camera3D::Projection;
using View = Camera3D::StandardView;

namespace {

const QSize pictureSize(400, 300);

/// A view of a kind's home pose that has a reference picture, view3d-KIND-NAME.png in the data
/// folder: what the kind looks like from where its parts are told apart best.
struct ReferenceView {
    const char *name;
    View view;
    Projection projection;
};

/// The reference views of every kind. A kind that is not here fails matchesReferencePicture by
/// name: a new kind gets its pictures (PKM_UPDATE_REFERENCE_IMAGES=1) when it is added.
const std::map<QString, std::vector<ReferenceView>> &referenceViews()
{
    static const std::map<QString, std::vector<ReferenceView>> views {
        {QStringLiteral("pjoint"),
            {{"isometric", View::Isometric, Projection::Perspective},
                {"front-orthographic", View::Front, Projection::Orthographic}}},
        {QStringLiteral("moma"), {{"isometric", View::Isometric, Projection::Perspective},
                                     {"top-orthographic", View::Top, Projection::Orthographic}}},
        {QStringLiteral("oxglide"),
            {{"isometric", View::Isometric, Projection::Perspective},
                {"front-orthographic", View::Front, Projection::Orthographic}}},
        // the planar linkages stand upright on their supports: from the front their links show
        {QStringLiteral("fourbar"),
            {{"isometric", View::Isometric, Projection::Perspective},
                {"front-orthographic", View::Front, Projection::Orthographic}}},
        {QStringLiteral("fivebar"),
            {{"isometric", View::Isometric, Projection::Perspective},
                {"front-orthographic", View::Front, Projection::Orthographic}}},
        {QStringLiteral("planar-parallel"),
            {{"isometric", View::Isometric, Projection::Perspective},
                {"front-orthographic", View::Front, Projection::Orthographic}}},
    };
    return views;
}

Camera3D fixedCamera(const Scene3D &scene, View view, Projection projection)
{
    Camera3D camera;
    camera.setViewport(pictureSize.width(), pictureSize.height());
    camera.setProjection(projection);
    camera.setStandardView(view);
    camera.fit(modelBounds(scene));
    return camera;
}

struct Difference {
    double mean = 0.0; ///< mean absolute difference per channel
    double farFraction = 0.0; ///< pixels with a channel off by more than 40
};

Difference compare(const QImage &a, const QImage &b)
{
    Difference d;
    if (a.size() != b.size())
        return {255.0, 1.0};
    const QImage x = a.convertToFormat(QImage::Format_RGB32), y = b.convertToFormat(QImage::Format_RGB32);
    qint64 sum = 0, far = 0;
    for (int row = 0; row < x.height(); ++row) {
        const auto *p = reinterpret_cast<const QRgb *>(x.constScanLine(row));
        const auto *q = reinterpret_cast<const QRgb *>(y.constScanLine(row));
        for (int column = 0; column < x.width(); ++column) {
            const int dr = std::abs(qRed(p[column]) - qRed(q[column]));
            const int dg = std::abs(qGreen(p[column]) - qGreen(q[column]));
            const int db = std::abs(qBlue(p[column]) - qBlue(q[column]));
            sum += dr + dg + db;
            far += std::max({dr, dg, db}) > 40 ? 1 : 0;
        }
    }
    const double pixels = double(x.width()) * x.height();
    d.mean = double(sum) / (3.0 * pixels);
    d.farFraction = double(far) / pixels;
    return d;
}

bool nearColour(QRgb pixel, const QColor &colour, int tolerance = 2)
{
    return std::abs(qRed(pixel) - colour.red()) <= tolerance && std::abs(qGreen(pixel) - colour.green()) <= tolerance
        && std::abs(qBlue(pixel) - colour.blue()) <= tolerance;
}

/// Pixels that are not the background.
double drawnFraction(const QImage &image)
{
    qint64 drawn = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            drawn += nearColour(image.pixel(x, y), Renderer3D::backgroundColour(), 3) ? 0 : 1;
    return double(drawn) / (double(image.width()) * image.height());
}

/// The background at all four corners.
bool backgroundAtCorners(const QImage &image)
{
    const QColor background = Renderer3D::backgroundColour();
    const int r = image.width() - 1, b = image.height() - 1;
    return nearColour(image.pixel(0, 0), background) && nearColour(image.pixel(r, 0), background)
        && nearColour(image.pixel(0, b), background) && nearColour(image.pixel(r, b), background);
}

void keep(const QImage &image, const QString &name)
{
    const QString directory = QDir::temp().filePath(QStringLiteral("pkm-view3d"));
    QDir().mkpath(directory);
    image.save(directory + QLatin1Char('/') + name + QStringLiteral(".png"));
}

} // namespace

class TestView3D : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void cleanupTestCase() { m_view.reset(); }
    void matchesReferencePicture_data();
    void matchesReferencePicture();
    void poseChangesPicture();
    void largePictureMatchesSmall_data() { frameTime_data(); }
    void largePictureMatchesSmall();
    void widgetPaintsWhatRenderImageRenders();
    void renderImageBeforeShown();
    void projectionChangesPicture();
    void emptySceneShowsOnlyGround();
    void savePictureWritesPng();
    void labelsNameThePoints();
    void frameTime_data();
    void frameTime();
    void manySolidsFrameTime();

private:
    QImage render(const Scene3D &scene, const Camera3D &camera, const QSize &size = pictureSize)
    {
        m_view->setScene(scene);
        m_view->setCamera(camera);
        return m_view->renderImage(size);
    }

    std::unique_ptr<LinkageView3D> m_view;
};

void TestView3D::initTestCase()
{
    m_view = std::make_unique<LinkageView3D>();
    m_view->resize(pictureSize);
    m_view->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_view.get()));
    QTRY_VERIFY(m_view->frameCount() > 0 || !m_view->isGlAvailable());
    QVERIFY2(m_view->isGlAvailable(), qPrintable(m_view->glStatus()));
    qInfo("%s", qPrintable(m_view->glStatus()));
    // The model alone, as OpenGL draws it: the names over it are labelsNameThePoints()'s.
    QVERIFY(m_view->labelsShown());
    m_view->setLabelsShown(false);
}

void TestView3D::matchesReferencePicture_data()
{
    QTest::addColumn<QString>("kind");
    QTest::addColumn<View>("view");
    QTest::addColumn<Projection>("projection");
    QTest::addColumn<bool>("known"); // false: the kind has no reference views yet
    for (const MechanismKind &kind : mechanismKinds()) {
        const QString id = QString::fromStdString(std::string(kind.id));
        const auto views = referenceViews().find(id);
        if (views == referenceViews().end()) {
            QTest::addRow("%s without reference views", qPrintable(id)) << id << View::Isometric
                                                                       << Projection::Perspective << false;
            continue;
        }
        for (const ReferenceView &reference : views->second)
            QTest::addRow("%s-%s", qPrintable(id), reference.name)
                << id << reference.view << reference.projection << true;
    }
}

void TestView3D::matchesReferencePicture()
{
    QFETCH(QString, kind);
    QFETCH(View, view);
    QFETCH(Projection, projection);
    QFETCH(bool, known);
    QVERIFY2(known,
        qPrintable(QStringLiteral("no reference views of kind %1: add them to referenceViews() and write the pictures "
                                  "with PKM_UPDATE_REFERENCE_IMAGES=1")
                       .arg(kind)));
    const MechanismPtr m = makeKind(kind.toStdString());
    QVERIFY(m);
    const Scene3D scene = m->scene3d(m->homePose());
    const QImage image = render(scene, fixedCamera(scene, view, projection));
    QCOMPARE(image.size(), pictureSize);
    const QString name = QString::fromLatin1(QTest::currentDataTag());
    keep(image, name);
    QVERIFY(backgroundAtCorners(image));
    QVERIFY(drawnFraction(image) > 0.03);

    const QString reference = QStringLiteral(PKM_TEST_DATA_DIR "/view3d-") + name + QStringLiteral(".png");
    if (qgetenv("PKM_UPDATE_REFERENCE_IMAGES") == "1") {
        QDir().mkpath(QStringLiteral(PKM_TEST_DATA_DIR));
        QVERIFY(image.save(reference));
        qInfo("wrote %s", qPrintable(reference));
        return;
    }
    const QImage expected(reference);
    QVERIFY2(!expected.isNull(), qPrintable(QStringLiteral("no reference %1").arg(reference)));
    const Difference d = compare(image, expected);
    QVERIFY2(d.mean < 3.0 && d.farFraction < 0.01,
        qPrintable(QStringLiteral("mean %1, %2 % far off").arg(d.mean).arg(100.0 * d.farFraction)));
}

void TestView3D::poseChangesPicture()
{
    const MechanismPtr m = makeKind("pjoint");
    QVERIFY(m);
    const Pose home = m->homePose();
    const int theta = m->variableIndex("theta");
    QVERIFY(theta >= 0);
    const Interval range = m->variableRange(theta);
    const Result<Pose> moved = m->solveWith(home, theta, range.min + 0.15 * (range.max - range.min));
    QVERIFY(moved.ok());
    const Scene3D first = m->scene3d(home);
    const Camera3D camera = fixedCamera(first, View::Isometric, Projection::Perspective);
    const QImage before = render(first, camera);
    const QImage after = render(m->scene3d(*moved), camera);
    keep(after, QStringLiteral("pjoint-moved"));
    const Difference d = compare(before, after);
    QVERIFY2(d.farFraction > 0.03, qPrintable(QString::number(d.farFraction)));
    // The extent does not move with the pose: the background stays at the corners.
    QVERIFY(backgroundAtCorners(after));
}

void TestView3D::largePictureMatchesSmall()
{
    QFETCH(QString, kind);
    const MechanismPtr m = makeKind(kind.toStdString());
    QVERIFY(m);
    const Scene3D scene = m->scene3d(m->homePose());
    const Camera3D camera = fixedCamera(scene, View::Isometric, Projection::Perspective);
    const QImage small = render(scene, camera);
    const QImage large = render(scene, camera, QSize(1600, 1200));
    QCOMPARE(large.size(), QSize(1600, 1200));
    keep(large, kind + QStringLiteral("-large"));
    QVERIFY(backgroundAtCorners(large));
    QVERIFY(drawnFraction(large) > 0.03);
    // The same picture, only sharper: scaled down it matches the small one but for edges.
    const QImage reduced = large.scaled(pictureSize, Qt::IgnoreAspectRatio, Qt::SmoothTransformation);
    const Difference d = compare(reduced, small);
    QVERIFY2(d.mean < 4.0 && d.farFraction < 0.03,
        qPrintable(QStringLiteral("mean %1, %2 % far off").arg(d.mean).arg(100.0 * d.farFraction)));
}

void TestView3D::widgetPaintsWhatRenderImageRenders()
{
    const MechanismPtr m = makeKind("pjoint");
    QVERIFY(m);
    const Scene3D scene = m->scene3d(m->homePose());
    const Camera3D camera = fixedCamera(scene, View::Isometric, Projection::Perspective);
    const QImage offscreen = render(scene, camera);
    const int frames = m_view->frameCount();
    const QImage frame = m_view->grabFrame();
    QVERIFY(m_view->frameCount() > frames);
    QCOMPARE(frame.size(), pictureSize * m_view->devicePixelRatioF());
    const Difference d = compare(frame.scaled(pictureSize), offscreen);
    QVERIFY2(d.mean < 3.0, qPrintable(QString::number(d.mean)));
    // on the CPU a frame in motion has one sample, and the frame the view rests on four
    QCOMPARE(m_view->lastFrameSamples(), m_view->glStatus().contains(QLatin1String("llvmpipe")) ? 1 : 4);
    QTRY_COMPARE(m_view->lastFrameSamples(), 4);
}

void TestView3D::renderImageBeforeShown()
{
    // A view never shown has no context of its own yet: it renders in a private one (the
    // path a command-line export takes), and gets the same picture.
    const MechanismPtr m = makeKind("moma");
    QVERIFY(m);
    const Scene3D scene = m->scene3d(m->homePose());
    const Camera3D camera = fixedCamera(scene, View::Isometric, Projection::Perspective);
    const QImage shown = render(scene, camera);
    LinkageView3D hidden;
    hidden.setLabelsShown(false); // as the shown one
    hidden.setScene(scene);
    hidden.setCamera(camera);
    QVERIFY(hidden.isGlAvailable());
    QVERIFY(hidden.hasGlSurface());
    QVERIFY(!hidden.hasGlContext());
    const QImage image = hidden.renderImage(pictureSize);
    QVERIFY2(!image.isNull(), qPrintable(hidden.imageError()));
    const Difference d = compare(image, shown);
    QVERIFY2(d.mean < 1.0 && d.farFraction < 0.002, qPrintable(QString::number(d.mean)));
    QVERIFY(!hidden.hasGlContext()); // no context was made for the view
    hidden.finishFrame(); // nothing to draw on yet, and nothing failed
    QVERIFY(hidden.isGlAvailable());
}

void TestView3D::projectionChangesPicture()
{
    const MechanismPtr m = makeKind("pjoint");
    QVERIFY(m);
    const Scene3D scene = m->scene3d(m->homePose());
    const QImage perspective = render(scene, fixedCamera(scene, View::Isometric, Projection::Perspective));
    QSignalSpy spy(m_view.get(), &LinkageView3D::projectionChanged);
    m_view->setProjection(Projection::Orthographic);
    QCOMPARE(spy.count(), 1);
    QCOMPARE(m_view->projection(), Projection::Orthographic);
    const QImage orthographic = m_view->renderImage(pictureSize);
    keep(orthographic, QStringLiteral("pjoint-isometric-orthographic"));
    QVERIFY(compare(perspective, orthographic).farFraction > 0.01);
    m_view->setProjection(Projection::Perspective);
    QCOMPARE(spy.count(), 2);
}

void TestView3D::emptySceneShowsOnlyGround()
{
    for (const bool withExtent : {false, true}) {
        Scene3D scene;
        if (withExtent)
            scene.extent = Eigen::AlignedBox3d(Eigen::Vector3d(-50, -20, -30), Eigen::Vector3d(150, 100, 30));
        Camera3D camera;
        camera.setViewport(pictureSize.width(), pictureSize.height());
        camera.setStandardView(View::Isometric);
        camera.setDistance(600.0);
        camera.setTarget(withExtent ? Eigen::Vector3d(50, 40, 0) : Eigen::Vector3d::Zero());
        const QImage image = render(scene, camera);
        QCOMPARE(image.size(), pictureSize);
        keep(image, withExtent ? QStringLiteral("empty-extent") : QStringLiteral("empty"));
        QVERIFY(backgroundAtCorners(image));
        // Grid lines only: something drawn, nothing coloured and nothing dark.
        QVERIFY(drawnFraction(image) > 0.005);
        for (int y = 0; y < image.height(); ++y) {
            for (int x = 0; x < image.width(); ++x) {
                const QColor c = image.pixelColor(x, y);
                QVERIFY(qGray(c.rgb()) > 170);
                QVERIFY(std::max({c.red(), c.green(), c.blue()}) - std::min({c.red(), c.green(), c.blue()}) < 30);
            }
        }
    }
}

void TestView3D::savePictureWritesPng()
{
    View3DPanel panel;
    const MechanismPtr m = makeKind("moma");
    QVERIFY(m);
    panel.setScene(m->scene3d(m->homePose()));
    panel.resize(520, 420);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    QVERIFY(panel.view()->isGlAvailable());
    QTemporaryDir directory;
    const QString path = directory.filePath(QStringLiteral("moma.png"));
    QString error;
    QVERIFY2(panel.savePicture(path, &error), qPrintable(error));
    const QImage saved(path);
    QCOMPARE(saved.size(), 2 * panel.view()->size());
    QVERIFY(backgroundAtCorners(saved));
    QVERIFY(drawnFraction(saved) > 0.05);
    const QString unwritable = directory.filePath(QStringLiteral("missing/moma.png"));
    QVERIFY(!panel.savePicture(unwritable, &error));
    QVERIFY(error.contains(unwritable));
    // any size: a 4K picture, and a size that is no picture refused with the reason
    const QString large = directory.filePath(QStringLiteral("moma-4k.png"));
    QVERIFY2(panel.savePicture(large, QSize(3840, 2160), &error), qPrintable(error));
    QCOMPARE(QImage(large).size(), QSize(3840, 2160));
    QVERIFY(!panel.savePicture(directory.filePath(QStringLiteral("tiny.png")), QSize(4, 4), &error));
    QVERIFY(error.contains(QStringLiteral("16 to 8000")));
    QVERIFY(!QFile::exists(directory.filePath(QStringLiteral("tiny.png"))));
}

void TestView3D::frameTime_data()
{
    addKindRows();
}

void TestView3D::frameTime()
{
    // A slider drag: every frame solves a pose, builds its model, tessellates, uploads and
    // draws it. grabFramebuffer() waits for the frame to finish (it reads it back).
    QFETCH(QString, kind);
    const MechanismPtr m = makeKind(kind.toStdString());
    QVERIFY(m);
    const Pose home = m->homePose();
    // The slider that goes furthest with the others held: the first input, unless another one
    // moves further (the five-bar's first crank reaches little of its range with the other
    // one held at its home angle).
    std::vector<Pose> poses;
    for (int variable = 0; variable < m->inputCount(); ++variable) {
        const Interval range = m->variableRange(variable);
        std::vector<Pose> along;
        for (int i = 0; i < 60; ++i) {
            const Result<Pose> pose
                = m->solveWith(home, variable, range.min + (range.max - range.min) * (0.2 + 0.6 * i / 59.0));
            if (pose.ok())
                along.push_back(*pose);
        }
        if (along.size() > poses.size())
            poses = std::move(along);
    }
    QVERIFY(poses.size() >= 30);
    m_view->setCamera(fixedCamera(m->scene3d(home), View::Isometric, Projection::Perspective));
    const int frames = m_view->frameCount();
    QElapsedTimer timer;
    qint64 sceneNanoseconds = 0;
    timer.start();
    for (const Pose &pose : poses) {
        QElapsedTimer sceneTimer;
        sceneTimer.start();
        m_view->setScene(m->scene3d(pose));
        sceneNanoseconds += sceneTimer.nsecsElapsed();
        QVERIFY(!m_view->grabFrame().isNull());
    }
    const double total = double(timer.nsecsElapsed()) / 1e6 / double(poses.size());
    QCOMPARE(m_view->frameCount(), frames + int(poses.size()));
    qInfo("%s: %zu solids, %zu triangles; per frame %.2f ms (scene3d + setScene %.3f ms) at %dx%d under %s",
        qPrintable(kind), m->scene3d(home).solids.size(), Mesh3D::fromScene(m->scene3d(home)).triangleCount(), total,
        double(sceneNanoseconds) / 1e6 / double(poses.size()), m_view->width(), m_view->height(),
        qPrintable(m_view->glStatus()));
}

void TestView3D::manySolidsFrameTime()
{
    // A few hundred solids (a third each boxes, pins and balls) moving every frame.
    auto model = [](double phase) {
        Scene3D scene;
        for (int i = 0; i < 300; ++i) {
            const Eigen::Vector3d p(40.0 * (i % 20), 40.0 * (i / 20) + 10.0 * std::sin(phase + i), 0.0);
            if (i % 3 == 0)
                scene.solids.push_back(
                    Solid::box(p, p + Eigen::Vector3d(30, 8, 0), 8, 4, Eigen::Vector3d::UnitZ(), PartRole::Link));
            else if (i % 3 == 1)
                scene.solids.push_back(Solid::cylinder(p, p + Eigen::Vector3d(0, 0, 12), 4, PartRole::Joint));
            else
                scene.solids.push_back(Solid::sphere(p, 5, PartRole::Marker));
        }
        scene.extent = Eigen::AlignedBox3d(Eigen::Vector3d(-20, -30, -20), Eigen::Vector3d(800, 630, 20));
        return scene;
    };
    m_view->setCamera(fixedCamera(model(0.0), View::Isometric, Projection::Perspective));
    constexpr int frames = 30;
    QElapsedTimer timer;
    qint64 sceneNanoseconds = 0;
    timer.start();
    for (int i = 0; i < frames; ++i) {
        const Scene3D scene = model(0.2 * i);
        QElapsedTimer sceneTimer;
        sceneTimer.start();
        m_view->setScene(scene);
        sceneNanoseconds += sceneTimer.nsecsElapsed();
        QVERIFY(!m_view->grabFrame().isNull());
    }
    const QImage image = m_view->renderImage(pictureSize);
    keep(image, QStringLiteral("many-solids"));
    QVERIFY(drawnFraction(image) > 0.03);
    qInfo("300 solids, %zu triangles: per frame %.2f ms (setScene %.3f ms)",
        Mesh3D::fromScene(model(0.0)).triangleCount(), double(timer.nsecsElapsed()) / 1e6 / frames,
        double(sceneNanoseconds) / 1e6 / frames);
}
void TestView3D::labelsNameThePoints() // where they go: tst_labels3d
{
    const MechanismPtr m = makeKind("pjoint");
    const Scene3D scene = m->scene3d(m->homePose());
    const Camera3D camera = fixedCamera(scene, View::Front, Projection::Orthographic);
    auto shot = [&](bool names) { m_view->setLabelsShown(names); return render(scene, camera); };
    const QImage bare = shot(false), named = shot(true);
    QVERIFY(compare(named, bare).farFraction > 0.002); // four names drawn
    QCOMPARE(compare(shot(false), bare).farFraction, 0.0); // and gone when off
}

QTEST_MAIN(TestView3D)
#include "tst_view3d.moc"
