#pragma once
/// The Tolerances dock (issue 19, part 5): ±tolerances of the geometric design parameters,
/// edited through the document (undoable, saved with the design); the first-order worst case
/// and each parameter's part of it at the current pose, live (a few solves per parameter); the
/// Monte Carlo and the worst-case map off the GUI thread (backgroundtask.h: progress, Cancel),
/// shown as a histogram or a colour map (QCustomPlot). The numbers are core/tolerance.h's.

#include "tolerancemap.h"

#include <QWidget>

#include <memory>
#include <optional>
#include <vector>

class QCustomPlot;
class QLabel;
class QPushButton;
class QSpinBox;
class QTableWidget;
class QTabWidget;
class QCheckBox;

namespace pkm {

class Document;

class TolerancePanel : public QWidget
{
    Q_OBJECT

public:
    explicit TolerancePanel(Document *document, QWidget *parent = nullptr);

    /// Runs the Monte Carlo now (as the button does); for tests.
    void runMonteCarlo();
    /// Computes the worst-case map (as the button does); for tests.
    void runMap();
    /// The last Monte Carlo shown, if any.
    const std::optional<tolerance::MonteCarlo> &monteCarlo() const { return m_monteCarlo; }

protected:
    void changeEvent(QEvent *event) override;

private:
    /// The parameter rows and their values, for a new design (or new tolerances).
    void rebuildRows();
    /// The first order at the pose: contributions and the summary line.
    void updateFirstOrder();
    void retranslate();
    void showHistogram();
    void showMap(const MapGrid &grid, const std::vector<float> &values, const MapSummary &summary);
    /// The analysis of the document's design and tolerances (made once per design and
    /// tolerance set: it builds the perturbed designs), or null and the message why there is none.
    std::shared_ptr<const tolerance::Analysis> analysis(QString *why = nullptr);

    Document *m_document;
    QTableWidget *m_table;
    QLabel *m_summary;
    QLabel *m_samplesLabel;
    QSpinBox *m_samples;
    QCheckBox *m_normal;
    QPushButton *m_runButton;
    QPushButton *m_mapButton;
    QPushButton *m_clearButton;
    QLabel *m_result;
    QCustomPlot *m_plot;
    QTabWidget *m_tabs;
    std::vector<std::string> m_names; ///< the parameter of each table row
    bool m_filling = false;
    std::optional<tolerance::MonteCarlo> m_monteCarlo;
    std::shared_ptr<const tolerance::Analysis> m_analysis;
    QString m_why;
    bool m_analysisValid = false;
};

} // namespace pkm
