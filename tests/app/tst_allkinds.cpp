// Every registered mechanism kind and every preset through the whole program, one data row each
// (a preset, or a kind's default design at its home pose), so that a new kind or preset is
// tested without a list to edit: the kinematics round-trip at the stored and the home pose,
// the Jacobians agree with central finite differences of the kinematics, the report is filled,
// the 2D and 3D drawings have parts, the mobility analysis runs, and every export is written —
// the parameter sheet (JSON and PDF), the DXF drawing and the 2D picture (PNG and SVG).
#include "export/dxfwriter.h"
#include "export/scenepicture.h"
#include "export/sheet.h"
#include "kinds/kindmodule.h"
#include "gui/viewpicture.h"
#include "mobility.h"
#include "registry.h"
#include "scenepainter.h"
#include "support/app.h"
#include "support/kinematics.h"
#include "support/process.h"

#include <QFile>
#include <QFileInfo>
#include <QImage>
#include <QJsonArray>
#include <QJsonObject>
#include <QPainter>
#include <QSet>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <vector>

using namespace pkm;
using namespace pkm::test;

namespace {

/// Round trips are exact but for rounding: 1e-9 of each coordinate (of 1 core unit, mm or rad,
/// at the least, so that a coordinate near 0 is not held to a tighter absolute bound).
constexpr double roundTripTolerance = 1e-9;
/// Central differences with a step of 1e-6 of the coordinates' size: truncation (h²) and
/// rounding (ε/h) are both far below this, relative to the Jacobian's size.
constexpr double differenceStep = 1e-6;
constexpr double differenceTolerance = 1e-6;
/// Below this singularity margin a Jacobian is ill-conditioned and its finite differences are
/// not a fair check (the kinds' own tests go there with their closed forms).
constexpr double regularMargin = 0.05;

/// Each coordinate of `actual` equals that of `wanted` to `tolerance` relative (see above).
bool sameCoordinates(const Coordinates &actual, const Coordinates &wanted, double tolerance = roundTripTolerance)
{
    if (actual.size() != wanted.size())
        return false;
    for (Eigen::Index i = 0; i < actual.size(); ++i) {
        if (!(std::abs(actual[i] - wanted[i]) <= tolerance * std::max(1.0, std::abs(wanted[i]))))
            return false;
    }
    return true;
}

QByteArray shown(const Coordinates &c)
{
    QByteArray out = "(";
    for (Eigen::Index i = 0; i < c.size(); ++i)
        out += (i ? ", " : "") + QByteArray::number(c[i], 'g', 17);
    return out + ")";
}

/// The poses of a design to check: the stored one (a preset's, or a kind's home pose) and the
/// design's home pose when that is another.
std::vector<std::pair<const char *, Pose>> posesOf(const Design &design)
{
    std::vector<std::pair<const char *, Pose>> poses {{"stored pose", design.pose}};
    const Pose home = design.mechanism->homePose();
    if (!sameCoordinates(home.inputs, design.pose.inputs, 0.0)
        || !sameCoordinates(home.outputs, design.pose.outputs, 0.0))
        poses.emplace_back("home pose", home);
    return poses;
}

double largest(const Eigen::MatrixXd &m)
{
    return m.size() ? m.cwiseAbs().maxCoeff() : 0.0;
}

/// The name of a row's design in files and captions: the preset's id or "default-KIND".
QString nameOf(const Design &design)
{
    return design.id.isEmpty() ? QStringLiteral("default-") + QString::fromUtf8(design.mechanism->kind().data())
                               : design.id;
}

} // namespace

/// Loads the design of the current row into `design`, or fails the row with the reason.
#define PKM_ROW_DESIGN(design)                                                                                         \
    const Result<Design> loaded = designOfRow();                                                                       \
    QVERIFY2(loaded.ok(), loaded ? "" : loaded.failure().message.c_str());                                             \
    const Design &design = *loaded

class TestAllKinds : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_dir;

private slots:
    void initTestCase() { QVERIFY(m_dir.isValid()); }

    /// Every kind has a preset (so the GUI's tests reach it) and every preset names a kind.
    void presetsAndKinds()
    {
        QSet<QString> kinds;
        for (const MechanismKind &kind : mechanismKinds())
            kinds.insert(QString::fromUtf8(kind.id.data(), qsizetype(kind.id.size())));
        for (const PresetInfo &preset : everyPreset())
            QVERIFY2(kinds.contains(preset.kind), qPrintable(preset.id + QStringLiteral(": ") + preset.kind));
        for (const PresetInfo &preset : presetPerKind())
            QVERIFY2(!preset.id.isEmpty(), qPrintable(QStringLiteral("kind %1 has no preset").arg(preset.kind)));
    }

    /// x → q → x and q → x → q at the stored and the home pose, staying in the pose's mode.
    void roundTrips_data() { addEveryDesignRows(); }
    void roundTrips()
    {
        PKM_ROW_DESIGN(design);
        const Mechanism &m = *design.mechanism;
        for (const auto &[which, pose] : posesOf(design)) {
            const QByteArray where = QByteArray(which) + " q = " + shown(pose.inputs) + ", x = " + shown(pose.outputs);
            const Result<Pose> inverse = m.solveInverse(pose.outputs, &pose);
            QVERIFY2(inverse, where + ": " + (inverse ? "" : inverse.failure().message.c_str()));
            QVERIFY2(
                sameCoordinates(inverse->inputs, pose.inputs), where + ": inverse gives q = " + shown(inverse->inputs));
            const Result<Pose> back = m.solveDirect(inverse->inputs, &pose);
            QVERIFY2(back, where + ": " + (back ? "" : back.failure().message.c_str()));
            QVERIFY2(sameCoordinates(back->outputs, pose.outputs), where + ": x → q → x gives " + shown(back->outputs));
            QCOMPARE(back->mode, pose.mode);

            const Result<Pose> direct = m.solveDirect(pose.inputs, &pose);
            QVERIFY2(direct, where + ": " + (direct ? "" : direct.failure().message.c_str()));
            QVERIFY2(
                sameCoordinates(direct->outputs, pose.outputs), where + ": direct gives x = " + shown(direct->outputs));
            const Result<Pose> again = m.solveInverse(direct->outputs, &pose);
            QVERIFY2(again, where + ": " + (again ? "" : again.failure().message.c_str()));
            QVERIFY2(sameCoordinates(again->inputs, pose.inputs), where + ": q → x → q gives " + shown(again->inputs));
            QCOMPARE(again->mode, pose.mode);
        }
    }

    /// Mechanism::jacobians against central differences of the kinematics: the inverse
    /// kinematics' ∂q/∂x is J, the direct kinematics' ∂x/∂q undoes it, and J_q·J = J_x.
    void jacobians_data() { addEveryDesignRows(); }
    void jacobians()
    {
        PKM_ROW_DESIGN(design);
        const Mechanism &m = *design.mechanism;
        int checked = 0;
        for (const auto &[which, pose] : posesOf(design)) {
            Singularity singularity;
            evaluated(m, pose, &singularity);
            if (singularity.margin < regularMargin) {
                qInfo("%s: singularity margin %g, not compared", which, singularity.margin);
                continue;
            }
            const QByteArray where = QByteArray(which) + " q = " + shown(pose.inputs) + ", x = " + shown(pose.outputs);
            const Jacobians j = m.jacobians(pose);
            QCOMPARE(j.full.rows(), Eigen::Index(m.inputCount()));
            QCOMPARE(j.full.cols(), Eigen::Index(m.outputCount()));
            QVERIFY2(largest(j.inputs * j.full - j.outputs) <= 1e-9 * std::max(1.0, largest(j.outputs)), where);

            const double hx = differenceStep * std::max(1.0, pose.outputs.cwiseAbs().maxCoeff());
            const std::optional<Eigen::MatrixXd> inverse = inverseDifferences(m, pose.outputs, hx, &pose);
            QVERIFY2(inverse, where + ": a step of the outputs cannot be solved");
            const double inverseGap = largest(*inverse - j.full) / std::max(1.0, largest(j.full));
            QVERIFY2(inverseGap <= differenceTolerance, where + ": ∂q/∂x off J by " + QByteArray::number(inverseGap));

            const double hq = differenceStep * std::max(1.0, pose.inputs.cwiseAbs().maxCoeff());
            const std::optional<Eigen::MatrixXd> direct = directDifferences(m, pose.inputs, hq, &pose);
            QVERIFY2(direct, where + ": a step of the inputs cannot be solved");
            const Eigen::MatrixXd identity = Eigen::MatrixXd::Identity(m.outputCount(), m.outputCount());
            const double directGap
                = largest(*direct * j.full - identity) / std::max(1.0, largest(*direct) * largest(j.full));
            QVERIFY2(directGap <= differenceTolerance, where + ": ∂x/∂q·J off I by " + QByteArray::number(directGap));
            ++checked;
        }
        // every design here has a regular stored or home pose: a row that checked none fails
        QVERIFY2(checked > 0, "every pose of this design is near a singularity");
    }

    /// evaluate() writes every value of the layout — the same whatever the buffer held before —
    /// and a value that is not finite is one the report shows as undefined: a quantity the
    /// pose has none of (derived), or any at a singular pose.
    void report_data() { addEveryDesignRows(); }
    void report()
    {
        PKM_ROW_DESIGN(design);
        const Mechanism &m = *design.mechanism;
        const ReportLayout &layout = m.reportLayout();
        std::vector<double> filled(std::size_t(layout.size), 0.5e300);
        const Singularity s = m.evaluate(design.pose, filled);
        Singularity again;
        const std::vector<double> fromNaN = evaluated(m, design.pose, &again);
        QCOMPARE(again.type, s.type);
        QVERIFY2(std::isfinite(s.margin) && s.margin >= 0.0, QByteArray::number(s.margin));
        for (const ReportEntry &entry : layout.entries) {
            for (int i = 0; i < entry.rows * entry.cols; ++i) {
                const std::size_t at = std::size_t(entry.offset + i);
                const QByteArray name = QByteArray::fromStdString(entry.name) + "[" + QByteArray::number(i) + "]";
                QVERIFY2(filled[at] == fromNaN[at] || (std::isnan(filled[at]) && std::isnan(fromNaN[at])),
                    name + " is not written: " + QByteArray::number(filled[at]) + " or "
                        + QByteArray::number(fromNaN[at]));
                if (std::isfinite(filled[at]))
                    continue;
                QVERIFY2(entry.group == ReportGroup::Derived || s.type != SingularityType::None,
                    name + " is not finite at a regular pose");
                qInfo("%s undefined at this pose (%g)", name.constData(), filled[at]);
            }
        }
    }

    /// The 2D scene and the 3D model of the stored pose have parts and a size.
    void scenes_data() { addEveryDesignRows(); }
    void scenes()
    {
        PKM_ROW_DESIGN(design);
        const Scene scene = design.mechanism->scene(design.pose);
        QVERIFY(!scene.joints.empty());
        QVERIFY(!scene.bars.empty() || !scene.guides.empty() || !scene.actuators.empty());
        QVERIFY(!scene.extent.isEmpty());
        const Scene3D model = design.mechanism->scene3d(design.pose);
        QVERIFY(!model.solids.empty());
        QVERIFY(!model.extent.isEmpty());
        // the 3D view names the model's points, each once, at a point of the model (a pole
        // such as the four-bar's P may lie outside the extent, on a marker of its own)
        QVERIFY(!model.labels.empty());
        Eigen::AlignedBox3d grown = model.extent;
        for (const Solid &solid : model.solids)
            grown.extend(solidBounds(solid));
        const Eigen::Vector3d margin = 0.05 * grown.sizes();
        grown.extend(grown.min() - margin).extend(grown.max() + margin);
        for (std::size_t i = 0; i < model.labels.size(); ++i) {
            const Label3D &label = model.labels[i];
            QVERIFY(!label.text.empty());
            QVERIFY2(grown.contains(label.at), label.text.c_str());
            for (std::size_t j = 0; j < i; ++j)
                QVERIFY2(model.labels[j].text != label.text, label.text.c_str());
        }
    }

    /// The mobility analysis of the pose's kinematic chain runs; at a regular pose the
    /// mechanism can move.
    void mobility_data() { addEveryDesignRows(); }
    void mobility()
    {
        PKM_ROW_DESIGN(design);
        const KinematicChain chain = design.mechanism->kinematicChain(design.pose);
        QVERIFY(chain.links.size() >= 2);
        QVERIFY(!chain.pairs.empty());
        const MobilityReport r = analyseMobility(chain);
        QVERIFY2(r.valid, r.verdict.c_str());
        QVERIFY(!r.verdict.empty());
        QVERIFY(r.actuators >= 1);
        QVERIFY(r.numerical >= r.mobility);
        // the finite mobility (the rank at regular poses next to this one) holds at a singular
        // pose too, where the rank drops and only the instantaneous one grows
        QVERIFY2(r.mobility >= 1, r.verdict.c_str());
    }

    /// The parameter sheet as JSON and as PDF: written, not empty, and the JSON is the sheet of
    /// this design.
    void parameterSheet_data() { addEveryDesignRows(); }
    void parameterSheet()
    {
        PKM_ROW_DESIGN(design);
        const QString name = nameOf(design);
        const sheet::Source source {name.toStdString(), design.title, design.description, design.requirements};
        const sheet::Sheet built = kinds::buildSheet(*design.mechanism, design.pose, source);
        QVERIFY(!built.sections.empty());
        // A kind whose module adds sections of its own gets them on top of the generic ones.
        const KindModule *module = kinds::find(design.mechanism->kind());
        if (module && module->sheetSections) {
            const sheet::Sheet generic = sheet::build(*design.mechanism, design.pose, source);
            std::size_t items = 0, genericItems = 0;
            for (const sheet::Section &section : built.sections)
                items += section.items.size() + section.tables.size() + section.checks.size() + section.figures.size();
            for (const sheet::Section &section : generic.sections)
                genericItems += section.items.size() + section.tables.size() + section.checks.size() + section.figures.size();
            QVERIFY2(items > genericItems, qPrintable(name));
        }
        const QString json = m_dir.filePath(name + QStringLiteral(".json"));
        const QString pdf = m_dir.filePath(name + QStringLiteral(".pdf"));
        for (const QString &path : {json, pdf}) {
            const std::optional<std::string> failure = sheet::save(built, path.toStdString());
            QVERIFY2(!failure, failure ? failure->c_str() : "");
            QVERIFY2(QFileInfo(path).size() > 0, qPrintable(path));
        }
        const QJsonObject read = readJson(json);
        QCOMPARE(read.value(QStringLiteral("design")).toString(), name);
        QCOMPARE(
            read.value(QStringLiteral("mechanism")).toString(), QString::fromUtf8(design.mechanism->kind().data()));
        QVERIFY(!read.value(QStringLiteral("sections")).toObject().isEmpty());
        QVERIFY(fileBytes(pdf).startsWith("%PDF-"));
    }

    /// The DXF drawing and the 2D picture (PNG, SVG) of the stored pose: written, not empty.
    void drawings_data() { addEveryDesignRows(); }
    void drawings()
    {
        PKM_ROW_DESIGN(design);
        const QString name = nameOf(design);
        const Scene scene = design.mechanism->scene(design.pose);
        const QString caption = pictures::poseCaption(*design.mechanism, design.pose, name);

        dxf::DrawingOptions options;
        options.caption = caption.toStdString();
        const dxf::Drawing drawing = dxf::sceneDrawing(scene, options);
        QVERIFY(drawing.entities > 0);
        QVERIFY(!drawing.extents.isEmpty());
        QVERIFY(drawing.dxf.find("AC1009") != std::string::npos);
        const QString dxfPath = m_dir.filePath(name + QStringLiteral(".dxf"));
        QFile dxfFile(dxfPath);
        QVERIFY(dxfFile.open(QIODevice::WriteOnly));
        QCOMPARE(dxfFile.write(drawing.dxf.data(), qint64(drawing.dxf.size())), qint64(drawing.dxf.size()));
        dxfFile.close();
        QVERIFY(QFileInfo(dxfPath).size() > 0);

        const SceneStyle style;
        QImage image(800, 600, QImage::Format_RGB32);
        image.fill(Qt::black); // not the picture's background: it must paint all of it
        {
            QPainter painter(&image);
            pictures::paintScenePicture(painter, QRectF(image.rect()), scene, style, caption);
        }
        qsizetype background = 0, drawn = 0;
        for (int y = 0; y < image.height(); y += 2) {
            for (int x = 0; x < image.width(); x += 2) {
                const QRgb pixel = image.pixel(x, y);
                background += qGray(pixel) > 200;
                drawn += qGray(pixel) < 160; // ink, links, actuators: darker than the grid
            }
        }
        const qsizetype samples = qsizetype(image.width() / 2) * (image.height() / 2);
        QVERIFY2(background > samples / 2, qPrintable(QString::number(background)));
        QVERIFY2(drawn > samples / 200, qPrintable(QString::number(drawn)));
        const QString png = m_dir.filePath(name + QStringLiteral(".png"));
        QVERIFY(image.save(png));
        QVERIFY(QFileInfo(png).size() > 0);

        QString error;
        PictureOptions svgOptions;
        svgOptions.size = QSize(800, 600);
        const QByteArray svg = viewpicture::posePicture(
            *design.mechanism, design.pose, name, style, QStringLiteral("svg"), svgOptions, QSize(800, 600), &error);
        QVERIFY2(svg.contains("<svg"), qPrintable(error));
    }
};

QTEST_MAIN(TestAllKinds)
#include "tst_allkinds.moc"
