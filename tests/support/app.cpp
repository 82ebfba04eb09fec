#include "support/app.h"

#include "gui/mainwindow.h"
#include "linkageview.h"
#include "registry.h"
#include "scenepainter.h"
#include "textscale.h"

#include <QApplication>
#include <QMenu>
#include <QMouseEvent>
#include <QSettings>
#include <QStandardPaths>

namespace pkm::test {

QList<PresetInfo> everyPreset()
{
    return designfile::presets();
}

QList<PresetInfo> presetPerKind()
{
    const QList<PresetInfo> presets = everyPreset();
    QList<PresetInfo> chosen;
    for (const MechanismKind &kind : mechanismKinds()) {
        const QString id = QString::fromUtf8(kind.id.data(), qsizetype(kind.id.size()));
        PresetInfo found {QString(), id, QString(), QString()};
        for (const PresetInfo &preset : presets) {
            if (preset.kind == id) {
                found = preset;
                break;
            }
        }
        chosen.append(found);
    }
    return chosen;
}

QString kindOfPreset(const QString &id)
{
    for (const PresetInfo &preset : everyPreset()) {
        if (preset.id == id)
            return preset.kind;
    }
    return {};
}

void addEveryPresetRows(const char *column)
{
    QTest::addColumn<QString>(column);
    for (const PresetInfo &preset : everyPreset())
        QTest::newRow(qPrintable(preset.id)) << preset.id;
}

void addPresetPerKindRows(const char *column)
{
    QTest::addColumn<QString>(column);
    for (const PresetInfo &preset : presetPerKind()) {
        if (preset.id.isEmpty())
            QTest::addRow("kind %s without a preset", qPrintable(preset.kind)) << QString();
        else
            QTest::newRow(qPrintable(preset.id)) << preset.id;
    }
}

void addEveryDesignRows()
{
    QTest::addColumn<QString>("preset");
    QTest::addColumn<QString>("kind");
    for (const PresetInfo &preset : everyPreset())
        QTest::addRow("preset %s", qPrintable(preset.id)) << preset.id << preset.kind;
    for (const MechanismKind &kind : mechanismKinds()) {
        const QString id = QString::fromUtf8(kind.id.data(), qsizetype(kind.id.size()));
        QTest::addRow("default %s", qPrintable(id)) << QString() << id;
    }
}

Result<Design> designOfRow()
{
    QFETCH(QString, preset);
    QFETCH(QString, kind);
    if (!preset.isEmpty())
        return designfile::load(preset);
    const std::string kindId = kind.toStdString();
    Result<MechanismPtr> made = createMechanism(kindId, {});
    if (!made)
        return made.failure();
    const MechanismKind *info = findMechanismKind(kindId);
    Design design;
    design.title = info ? QString::fromUtf8(info->title.data(), qsizetype(info->title.size())) : kind;
    design.mechanism = *made;
    design.pose = design.mechanism->homePose();
    return design;
}

MainWindow *freshMainWindow(const QSize &size)
{
    QStandardPaths::setTestModeEnabled(true);
    QSettings().clear();
    textscale::applyBaseFont(); // the font PKM Studio starts with: what fits is measured in it
    auto *window = new MainWindow;
    window->resize(size);
    window->show();
    if (!QTest::qWaitForWindowExposed(window)) {
        delete window;
        return nullptr;
    }
    return window;
}

void drag(QWidget *widget, QPointF from, QPointF to, int steps)
{
    QTest::mousePress(widget, Qt::LeftButton, Qt::NoModifier, from.toPoint());
    for (int i = 1; i <= steps; ++i) {
        // QTest::mouseMove carries no button: a drag needs the button held in the event
        const QPointF at = from + (to - from) * (double(i) / steps);
        QMouseEvent move(QEvent::MouseMove, at, widget->mapToGlobal(at), Qt::NoButton, Qt::LeftButton, Qt::NoModifier);
        QApplication::sendEvent(widget, &move);
    }
    QTest::mouseRelease(widget, Qt::LeftButton, Qt::NoModifier, to.toPoint());
}

QMenu *openMenu(QWidget *widget)
{
    for (QMenu *menu : widget->findChildren<QMenu *>()) {
        if (menu->isVisible())
            return menu;
    }
    return nullptr;
}

drawing::DrawList viewLayout(const LinkageView *view, drawing::LabelPlaces &places)
{
    drawing::LayoutOptions options;
    options.labelRoom = QRectF(view->rect()).adjusted(2.0, 2.0, -2.0, -2.0);
    for (const Scene &ghost : view->ghostScenes()) {
        const std::vector<QLineF> lines = drawing::ghostLines(ghost, view->mapping());
        options.avoid.insert(options.avoid.end(), lines.begin(), lines.end());
    }
    options.covered.push_back(ScenePainter::scaleBarBox(QRectF(view->rect()), view->mapping(), view->sceneStyle(), view));
    const drawing::LabelPlaces previous = places;
    options.previousLabels = &previous;
    options.placedLabels = &places;
    return drawing::layoutScene(view->scene(), view->mapping(), view->sceneStyle(), options);
}

} // namespace pkm::test
