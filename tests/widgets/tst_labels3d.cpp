// Where the 3D view puts the names of the points (labels3d.h), on a blank picture so that no
// OpenGL is needed: each name beside its point's projection and nowhere else, names of points
// that project together moved apart, points behind the camera or outside the picture unnamed.
#include "labels3d.h"

#include <QImage>
#include <QPainter>
#include <QTest>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

using namespace pkm;

namespace {

Camera3D frontCamera()
{
    Camera3D camera;
    camera.setViewport(400, 300);
    camera.setProjection(Camera3D::Projection::Orthographic);
    camera.setStandardView(Camera3D::StandardView::Front);
    camera.fit(Eigen::AlignedBox3d(Eigen::Vector3d(-100, -75, -10), Eigen::Vector3d(100, 75, 10)));
    return camera;
}

QImage painted(const std::vector<Label3D> &labels, const Camera3D &camera)
{
    QImage image(camera.viewportWidth(), camera.viewportHeight(), QImage::Format_RGB32);
    image.fill(QColor(0x80, 0x80, 0x80)); // grey, so the white knock-outs show too
    QPainter painter(&image);
    QFont font;
    font.setPixelSize(16);
    paintLabels3D(painter, labels, camera, font);
    return image;
}

/// The box around the pixels that differ from the grey background; empty when none do.
QRect changedArea(const QImage &image, const QRect &within)
{
    QRect box;
    for (int y = within.top(); y <= within.bottom(); ++y)
        for (int x = within.left(); x <= within.right(); ++x)
            if (image.pixel(x, y) != qRgb(0x80, 0x80, 0x80))
                box |= QRect(x, y, 1, 1);
    return box;
}

} // namespace

class TestLabels3D : public QObject
{
    Q_OBJECT

private slots:
    void nameSitsBesideItsPoint()
    {
        const Camera3D camera = frontCamera();
        const Eigen::Vector3d point(-40.0, 10.0, 0.0);
        const QImage image = painted({{point, "A"}}, camera);
        const Eigen::Vector2d at = camera.project(point);
        const QRect drawn = changedArea(image, image.rect());
        QVERIFY(!drawn.isEmpty());
        // the dot on the point, the name up and to the right of it, all within 40 pixels
        QVERIFY(drawn.contains(int(at.x()), int(at.y())));
        QVERIFY(drawn.right() > at.x() + 8 && drawn.top() < at.y() - 8);
        QVERIFY(drawn.left() > at.x() - 6 && drawn.bottom() < at.y() + 6);
        QVERIFY(drawn.width() < 40 && drawn.height() < 40);
    }

    void namesOfOnePointDoNotCoverEachOther()
    {
        const Camera3D camera = frontCamera();
        const Eigen::Vector3d point(0.0, 0.0, 0.0);
        const QImage one = painted({{point, "P₁"}}, camera);
        const QImage two = painted({{point, "P₁"}, {point + Eigen::Vector3d(0.5, 0.0, 0.0), "O_P"}}, camera);
        // the second name went to another corner: the drawing grows to the left of the point
        const Eigen::Vector2d at = camera.project(point);
        QVERIFY(changedArea(one, one.rect()).left() > at.x() - 6);
        QVERIFY(changedArea(two, two.rect()).left() < at.x() - 15);
    }

    /// A 3-leg platform drawn small: its corners' names piled on each other and on Oₚ. They
    /// are left out while the corners are closer than one and a half names, as in the 2D view;
    /// drawn larger, each corner is named.
    void smallPlatformNamesItsReferenceOnly()
    {
        const Camera3D camera = frontCamera();
        const auto platform = [](double size) {
            std::vector<Label3D> labels {{Eigen::Vector3d::Zero(), "Oₚ", false}};
            const std::array<const char *, 3> names {"P₁", "P₂", "P₃"};
            for (int k = 0; k < 3; ++k) {
                const double angle = 2.0 * std::numbers::pi * k / 3.0;
                labels.push_back({size * Eigen::Vector3d(std::cos(angle), std::sin(angle), 0.0), names[std::size_t(k)], true});
            }
            return labels;
        };
        const QImage reference = painted({{Eigen::Vector3d::Zero(), "Oₚ"}}, camera);
        const QImage small = painted(platform(3.0), camera); // corners about 10 px apart
        QCOMPARE(small, reference);
        const QImage large = painted(platform(40.0), camera); // about 140 px apart
        const Eigen::Vector2d corner = camera.project(Eigen::Vector3d(40.0, 0.0, 0.0));
        QVERIFY(!changedArea(large, QRect(int(corner.x()) - 2, int(corner.y()) - 30, 40, 32)).isEmpty());
        QVERIFY(changedArea(reference, QRect(int(corner.x()) - 2, int(corner.y()) - 30, 40, 32)).isEmpty());
    }

    void pointsOutOfSightAreNotNamed()
    {
        const Camera3D camera = frontCamera();
        const QImage image = painted({{Eigen::Vector3d(1e4, 0.0, 0.0), "far"},
                                      {camera.eye() + 10.0 * (camera.eye() - camera.target()), "behind"}},
                                     camera);
        QVERIFY(changedArea(image, image.rect()).isEmpty());
    }
};

QTEST_MAIN(TestLabels3D)
#include "tst_labels3d.moc"
