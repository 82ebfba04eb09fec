#pragma once
/// Helpers for the tests of the application: the presets and the registered kinds as data rows,
/// so that a test over "every preset" or "every kind" takes them from the program (a new preset
/// or kind is then tested without editing a list, and one that lacks what a test needs fails
/// with its name), and the main window opened afresh and driven with the mouse.

#include "document/designfile.h"
#include "scenelayout.h"

#include <QList>
#include <QPointF>
#include <QSize>
#include <QString>
#include <QTest>

class QMenu;
class QWidget;

namespace pkm {
class LinkageView;
class MainWindow;
}

namespace pkm::test {

// -- presets and kinds as data rows ----------------------------------------------------------

/// Every built-in preset (designfile::presets()), in its order.
QList<PresetInfo> everyPreset();

/// One preset of every registered kind, in the registry's order: the first of the kind in
/// designfile::presets(). A kind that has no preset gives an entry with its kind and an empty
/// id, so that a test over every kind fails on it by name (PKM_FETCH_PRESET) rather than
/// leave the kind out silently.
QList<PresetInfo> presetPerKind();

/// The kind of preset `id` (designfile::presets()); empty when there is no such preset.
QString kindOfPreset(const QString &id);

/// The column `column` (QString), one row per preset of everyPreset(), named by its id.
void addEveryPresetRows(const char *column = "preset");
/// The column `column` (QString), one row per entry of presetPerKind(), named by the preset's
/// id, or "kind K without a preset" with an empty id.
void addPresetPerKindRows(const char *column = "preset");

/// QFETCH(QString, column) for the rows above; fails the row of a kind without a preset.
#define PKM_FETCH_PRESET(column)                                                                                       \
    QFETCH(QString, column);                                                                                           \
    QVERIFY2(!column.isEmpty(), QTest::currentDataTag())

/// The columns "preset" (QString: empty for a kind's default design) and "kind" (QString):
/// one row per preset ("preset ID"), then one per registered kind's default design,
/// createMechanism(kind, {}) at its home pose ("default KIND").
void addEveryDesignRows();
/// The design of the current row of addEveryDesignRows(): the preset loaded, or the kind's
/// default design at its home pose (id and title empty); the failure names what went wrong.
Result<Design> designOfRow();

// -- the main window -------------------------------------------------------------------------

/// A main window as at a first start: test-mode settings (QStandardPaths) cleared, so that
/// every run starts from the default layout, resized to `size`, shown and exposed. Null when
/// it is never exposed. The caller deletes it.
MainWindow *freshMainWindow(const QSize &size);

/// Presses the left button at `from` in `widget`, moves it to `to` in `steps` steps and
/// releases it there (device pixels), as a hand drags.
void drag(QWidget *widget, QPointF from, QPointF to, int steps = 8);

/// The visible menu among the children of `widget` (a context menu it opened), or null.
QMenu *openMenu(QWidget *widget);

/// The 2D view's drawing laid out as the view paints it: its labels kept inside the view, off
/// the ghosts' lines and the scale bar, each where it stood the frame before (`places`, which
/// the layout updates, as the view keeps them from frame to frame).
drawing::DrawList viewLayout(const LinkageView *view, drawing::LabelPlaces &places);

} // namespace pkm::test
