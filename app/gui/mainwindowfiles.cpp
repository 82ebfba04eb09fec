// The main window's files: the Presets menu, opening, saving and recovering designs, the recent
// files, the window layout kept between sessions, and the exports — the animation, the DXF drawing, the
// parameter sheet and the picture of a view.

#include "gui/mainwindow.h"
#include "gui/mainwindowinternal.h"

#include "gui/animationdialog.h"
#include "export/animationplot.h"
#include "plotfocus.h"
#include "gui/backgroundtask.h"
#include "designpanel.h"
#include "document/designsession.h"
#include "document/document.h"
#include "export/dxfwriter.h"
#include "document/language.h"
#include "linkageview.h"
#include "linkageview3d.h"
#include "mobilitypanel.h"
#include "modebar.h"
#include "pictureexport.h"
#include "quantityformat.h"
#include "registry.h"
#include "export/sheet.h"
#include "valuestable.h"
#include "variablepanel.h"
#include "gui/viewpicture.h"
#include "workspacemapview.h"
#include "kinds/kindmodule.h"
#include "kinds/kindpanel.h"
#include "kinds/sweepplotspanel.h"
#include "kinds/workspacepanel.h"

#include <qcustomplot.h>

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QDir>
#include <QDockWidget>
#include <QFileInfo>
#include <QFileDialog>
#include <QLabel>
#include <QMap>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QSaveFile>
#include <QScrollArea>
#include <QSettings>
#include <QSplitter>
#include <QStackedWidget>
#include <QStatusBar>
#include <QTabWidget>
#include <QTimer>
#include <QToolBar>
#include <QUndoStack>
#include <QVBoxLayout>

#include <utility>

namespace pkm {

namespace {
using mainwindow::failureText;

constexpr int settingsVersion = 1;
} // namespace

void MainWindow::openFile()
{
    if (!maybeSave())
        return;
    const QString path = QFileDialog::getOpenFileName(this, tr("Open Design"), QFileInfo(m_session->filePath()).path(),
                                                      tr("PKM Studio designs (*.pkm.json);;All files (*)"));
    if (!path.isEmpty())
        openDesign(path);
}

void MainWindow::openFromMenu(const QString &presetOrPath)
{
    if (maybeSave())
        openDesign(presetOrPath);
}

bool MainWindow::saveFile()
{
    if (m_session->filePath().isEmpty())
        return saveFileAs();
    auto saved = m_session->save();
    if (!saved) {
        QMessageBox::warning(this, tr("Save Design"), failureText(saved.failure()));
        return false;
    }
    showStatus(tr("Saved %1").arg(m_session->filePath()));
    return true;
}

bool MainWindow::saveFileAs()
{
    QString path = QFileDialog::getSaveFileName(this, tr("Save Design As"), m_session->filePath(),
                                                tr("PKM Studio designs (*.pkm.json)"));
    if (path.isEmpty())
        return false;
    if (!path.endsWith(QLatin1String(".json")))
        path += QStringLiteral(".pkm.json");
    auto saved = m_session->saveAs(path);
    if (!saved) {
        QMessageBox::warning(this, tr("Save Design"), failureText(saved.failure()));
        return false;
    }
    showStatus(tr("Saved %1").arg(path));
    return true;
}

void MainWindow::fillPresetsMenu()
{
    // clear() leaves the submenus behind (hidden, in the old language): they go as well
    qDeleteAll(m_presetsMenu->findChildren<QMenu *>(QString(), Qt::FindDirectChildrenOnly));
    m_presetsMenu->clear();
    // A kind with several presets is a submenu named by the kind: one flat list of eighteen
    // was taller than a 720-pixel projector at a large text size, and Qt cut its titles.
    const QList<PresetInfo> presets = designfile::presets();
    QMap<QString, int> perKind;
    for (const PresetInfo &preset : presets)
        ++perKind[preset.kind];
    QString lastKind;
    QMenu *menu = m_presetsMenu;
    for (const PresetInfo &preset : presets) {
        if (preset.kind != lastKind) {
            menu = m_presetsMenu;
            if (perKind.value(preset.kind) > 1) {
                const MechanismKind *kind = findMechanismKind(preset.kind.toStdString());
                menu = m_presetsMenu->addMenu(kind ? coreLabel(kind->title) : preset.kind);
                menu->setObjectName(QStringLiteral("presets_") + preset.kind);
            }
        }
        lastKind = preset.kind;
        QAction *action = menu->addAction(designfile::presetText(preset.title), this,
                                          [this, id = preset.id] { openFromMenu(id); });
        action->setData(preset.id);
        action->setObjectName(QStringLiteral("preset_") + preset.id);
        // the description as the file gives it: loading every preset (solving its pose, a
        // 3-DOF design's home search) cost a start and every change of language 100–200 ms
        action->setToolTip(designfile::presetText(preset.description));
    }
}

void MainWindow::exportAnimationDialog()
{
    AnimationDialog dialog(*m_document->mechanism(), 0, this);
    dialog.restoreChoices();
    dialog.setStart(m_document->pose());
    QCustomPlot *shown = m_currentPanel ? plotfocus::active(m_currentPanel) : nullptr;
    if (shown)
        dialog.setShownPlot(plotfocus::title(shown));
    if (dialog.exec() != QDialog::Accepted)
        return;
    dialog.rememberChoices();
    const QString base = m_session->filePath().isEmpty() ? QFileInfo(m_document->design().id).fileName()
                                                         : QFileInfo(m_session->filePath()).completeBaseName();
    const QString path = chooseAnimationPath(this, base, dialog.fileExtension());
    if (path.isEmpty())
        return;
    exportAnimationTo(path, dialog.settings(), dialog.besideChoice());
}

void MainWindow::exportAnimationTo(const QString &path, AnimationSettings settings, const QString &beside)
{
    settings.name = m_session->displayName();
    const MechanismPtr mechanism = m_document->mechanism();
    if (beside == AnimationDialog::shownPlotChoice()) {
        QCustomPlot *shown = m_currentPanel ? plotfocus::active(m_currentPanel) : nullptr;
        if (shown)
            settings.beside = shownPlotPictures(m_currentPanel, shown);
    } else if (!beside.isEmpty()) {
        auto plot = animationPlot(*mechanism, m_document->pose(), settings, beside.toStdString());
        if (!plot) {
            showStatus(failureText(plot.failure()), true);
            return;
        }
        settings.beside = [plot = std::move(*plot), mechanism](const Pose &pose, const QSize &size) {
            return animationPlotImage(plot, *mechanism, pose, size);
        };
    }
    exportAnimation(this, mechanism, m_document->pose(), settings, path,
                    [this, panel = QPointer<KindPanel>(m_currentPanel)](const QString &message, bool error) {
                        if (panel) // the plot's cursors followed the frames: back to the pose
                            panel->setPose(m_document->pose());
                        showStatus(message, error);
                    });
}

bool MainWindow::maybeSave()
{
    if (!m_session->isModified())
        return true;
    const auto answer = m_question(tr("Unsaved Changes"),
                                   tr("The design “%1” has changes that are not saved. Save them?")
                                       .arg(m_session->displayName()),
                                   QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel);
    if (answer == QMessageBox::Save)
        return saveFile();
    return answer == QMessageBox::Discard;
}

void MainWindow::offerRecovery()
{
    for (const DesignSession::Recovery &recovery : DesignSession::pendingRecoveries()) {
        const QString name = recovery.originalPath.isEmpty() ? designfile::presetText(recovery.title) : recovery.originalPath;
        const auto answer =
            m_question(tr("Recover Design"),
                       tr("PKM Studio closed unexpectedly while “%1” had unsaved changes (autosaved %2). "
                          "Recover them?")
                           .arg(name, QLocale().toString(recovery.saved, QLocale::ShortFormat)),
                       QMessageBox::Yes | QMessageBox::No);
        if (answer != QMessageBox::Yes) {
            DesignSession::discardRecovery(recovery);
            continue;
        }
        auto recovered = m_session->recover(recovery);
        if (!recovered) {
            showStatus(failureText(recovered.failure()), true);
            continue;
        }
        m_view->fitToView();
        showStatus(tr("Recovered “%1”: save it to keep the changes.").arg(name));
        return; // one document at a time; older autosaves stay for the next start
    }
}

void MainWindow::updateTitle()
{
    // "[*]" is where Qt shows the unsaved-changes mark.
    setWindowTitle(tr("%1[*] — PKM Studio").arg(m_session->displayName()));
    setWindowModified(m_session->isModified());
}

void MainWindow::updateRecentMenu()
{
    m_recentMenu->clear();
    const QStringList files = m_session->recentFiles();
    for (const QString &path : files) {
        QAction *action = m_recentMenu->addAction(QFileInfo(path).fileName(), this, [this, path] {
            if (!QFileInfo::exists(path)) {
                showStatus(tr("%1 no longer exists; removed from the recent files.").arg(path), true);
                m_session->removeRecentFile(path);
                return;
            }
            openFromMenu(path);
        });
        action->setToolTip(path);
        action->setData(path);
    }
    m_recentMenu->setToolTipsVisible(true);
    m_recentMenu->setEnabled(!files.isEmpty());
}

void MainWindow::about()
{
    QMessageBox::about(this, tr("About PKM Studio"),
                       tr("<h3>PKM Studio %1</h3><p>Design, analysis and teaching of parallel-kinematic "
                          "mechanisms.</p><p>Licensed under the GNU General Public License, version 3 or "
                          "later.</p>")
                           .arg(QStringLiteral(PKM_VERSION)));
}

void MainWindow::sourceDocuments()
{
    // The four documents whose mechanisms PKM Studio models, cited as published (their titles
    // in their own languages), so that a student can look them up.
    const QString references = QStringLiteral(
        "<ol>"
        "<li>D. Milutinović, B. Kokotović, N. Slavković, S. Živanović: <i>Механизам активног "
        "П-зглоба као еквивалента комбинације обртног зглоба и сегмента константне дужине</i>, "
        "technical solution, University of Belgrade, Faculty of Mechanical Engineering, 2014.</li>"
        "<li>G. V. Vasilić, S. T. Živanović: <i>Modeliranje i analiza rekonfigurabilnog dvoosnog "
        "paralelnog mehanizma MOMA sa osnaženim translatornim zglobovima</i>, Tehnika, 2016, "
        "DOI 10.5937/tehnika1601057V.</li>"
        "<li>C. Mladenović, S. Tabaković, M. Zeljković: <i>Radni prostor O-X glide hibridnog "
        "mehanizma</i>, Faculty of Technical Sciences, University of Novi Sad.</li>"
        "<li>L. F. Khabibullina, F. F. Khabibullin, R. T. Islamov: <i>Параметрический синтез узлов "
        "мехатронных систем</i>, Kazan National Research Technical University named after "
        "A. N. Tupolev (KAI).</li>"
        "</ol>");
    auto *box = new QMessageBox(QMessageBox::Information, tr("Source Documents"),
        tr("<p>PKM Studio models the mechanisms of these four documents: the active П-joint (1), "
           "MOMA (2), the O-X glide (3), the four-bar and the mobility formulas (4). Where a printed "
           "formula or number is wrong, the program uses the corrected one; the README's section on "
           "the mathematics lists each correction.</p>%1")
            .arg(references),
        QMessageBox::Close, this);
    box->setObjectName(QStringLiteral("sourceDocuments"));
    box->setTextFormat(Qt::RichText);
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->open();
}

void MainWindow::restoreLayout()
{
    QSettings settings;
    if (settings.value(QStringLiteral("layout/version")).toInt() != settingsVersion)
        return;
    m_restoredGeometry = restoreGeometry(settings.value(QStringLiteral("layout/geometry")).toByteArray());
    restoreState(settings.value(QStringLiteral("layout/state")).toByteArray(), settingsVersion);
    m_splitter->restoreState(settings.value(QStringLiteral("layout/splitter")).toByteArray());
}

void MainWindow::closeEvent(QCloseEvent *event)
{
    if (!maybeSave()) {
        event->ignore();
        return;
    }
    setPresentationMode(false); // the layout remembered is the working one, docks and all
    QSettings settings;
    settings.setValue(QStringLiteral("layout/version"), settingsVersion);
    settings.setValue(QStringLiteral("layout/geometry"), saveGeometry());
    settings.setValue(QStringLiteral("layout/state"), saveState(settingsVersion));
    settings.setValue(QStringLiteral("layout/splitter"), m_splitter->saveState());
    event->accept();
}

void MainWindow::exportDrawing()
{
    // The linkage drawing of the current design and pose, the same file as `pkm dxf`.
    QString path = QFileDialog::getSaveFileName(this, tr("Export Drawing (DXF)"), QString(),
                                                tr("DXF drawings (*.dxf);;All files (*)"));
    if (path.isEmpty())
        return;
    if (QFileInfo(path).suffix().isEmpty())
        path += QStringLiteral(".dxf");
    const Design &design = m_document->design();
    const QString title = design.title.isEmpty() ? toQString(m_document->mechanism()->kind()) : design.title;
    dxf::DrawingOptions options;
    options.caption = (title + QStringLiteral(" — ") + poseSummary().simplified()).toStdString();
    const dxf::Drawing drawing = dxf::sceneDrawing(m_document->mechanism()->scene(m_document->pose()), options);
    QSaveFile file(path); // the file is replaced only once it is complete
    const auto size = static_cast<qint64>(drawing.dxf.size());
    if (!file.open(QIODevice::WriteOnly) || file.write(drawing.dxf.data(), size) != size || !file.commit()) {
        const QString message = tr("Cannot write the drawing to %1: %2.").arg(QDir::toNativeSeparators(path), file.errorString());
        showStatus(message, true);
        QMessageBox::warning(this, tr("Export Drawing (DXF)"), message);
        return;
    }
    showStatus(tr("Wrote the drawing to %1 (DXF R12, mm).").arg(QDir::toNativeSeparators(path)));
}

void MainWindow::exportParameterSheet()
{
    // The parameter sheet of the current design and pose, the same file as `pkm sheet`.
    QString filter;
    QString path = QFileDialog::getSaveFileName(this, tr("Export Parameter Sheet"), QString(),
        tr("PDF parameter sheets (*.pdf);;JSON (*.json);;CSV (*.csv)"), &filter);
    if (path.isEmpty())
        return;
    if (QFileInfo(path).suffix().isEmpty())
        path += filter.contains(QLatin1String("*.json")) ? QStringLiteral(".json")
            : filter.contains(QLatin1String("*.csv"))    ? QStringLiteral(".csv")
                                                         : QStringLiteral(".pdf");
    const Design &design = m_document->design();
    sheet::Source source;
    source.design = !design.id.isEmpty() ? design.id.toStdString()
        : !m_session->filePath().isEmpty() ? QFileInfo(m_session->filePath()).fileName().toStdString()
                                           : design.title.toStdString();
    source.title = design.title;
    source.description = design.description;
    source.requirements = design.requirements;
    // A planar workspace and its maps take a second or two: off the GUI thread.
    runInBackground(
        this, tr("Export Parameter Sheet"), tr("Computing the parameter sheet…"),
        [mechanism = m_document->mechanism(), pose = m_document->pose(), source,
         path](const std::atomic<bool> &) -> TaskFailure {
            const sheet::Sheet built = kinds::buildSheet(*mechanism, pose, source);
            if (const std::optional<std::string> failure = sheet::save(built, path.toStdString()))
                return QString::fromStdString(*failure);
            return std::nullopt;
        },
        [this, path](const TaskFailure &failure, bool) {
            if (failure) {
                showStatus(*failure, true);
                QMessageBox::warning(this, tr("Export Parameter Sheet"), *failure);
                return;
            }
            showStatus(tr("Wrote the parameter sheet to %1.").arg(QDir::toNativeSeparators(path)));
        });
}

void MainWindow::saveViewPicture()
{
    // The 2D picture of the current design and pose, the same drawing as `pkm render` (with the
    // velocity and force shapes when the view shows them).
    const Scene drawn = viewScene(m_document->pose());
    const QString path = viewpicture::savePictureAs(this, *m_document->mechanism(), m_document->pose(),
        m_session->displayName(), viewpicture::suggestedName(m_session->filePath(), m_document->design().id),
        m_view->size(), m_view->sceneStyle(), &drawn);
    if (!path.isEmpty())
        showStatus(tr("Wrote the 2D view to %1.").arg(QDir::toNativeSeparators(path)));
}

} // namespace pkm
