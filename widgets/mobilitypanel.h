#pragma once
/// The mobility of the current mechanism, for the classroom (docs/mathematics.md): the chain in
/// words, Chebyshev's and Somov–Malyshev's formulas with the numbers put in, the mobility from
/// the rank of the constraint Jacobian at the pose, the verdict, singular poses and the
/// actuation; and classroom examples (the spatial parallelogram, the Bennett linkage, a general
/// spatial 4R) that show where the formulas fail. A formula that fails is marked with a word
/// and a sign in the warning colour, never by colour alone.
///
/// analyseMobility() takes up to about 1.5 ms in a Release build (the O-X glide; 0.1–0.4 ms
/// for the planar mechanisms) and much more in a Debug build, so it runs off the GUI thread:
/// one analysis at a time, a newer request replacing the one waiting, results older than the
/// one shown dropped; and only while the panel is seen (visible, and the front tab when its
/// dock is tabified): a hidden panel catches up when it is shown.

#include "mechanism.h"
#include "mobility.h"

#include <QFutureWatcher>
#include <QPointer>
#include <QThreadPool>
#include <QWidget>

#include <map>
#include <optional>
#include <string>

class QComboBox;
class QDockWidget;
class QLabel;
class QTextBrowser;

namespace pkm {

class MobilityPanel : public QWidget
{
    Q_OBJECT

public:
    /// What the panel analyses: the entries of its combo box, in order.
    enum class Subject { ThisMechanism, SpatialParallelogram, BennettLinkage, SpatialFourR };
    /// The parts of the display (tests read them as plain text).
    enum class Part { Example, Chain, Singularity, Chebyshev, SomovMalyshev, Rank, Actuation, Verdict, Note };

    explicit MobilityPanel(QWidget *parent = nullptr);
    ~MobilityPanel() override;

    /// A new design; its chain is analysed at the pose given next (setPose()).
    void setMechanism(const MechanismPtr &mechanism);
    void setMechanism(const MechanismPtr &mechanism, const Pose &pose);
    void setPose(const Pose &pose);
    /// A chain of no particular mechanism (the mechanism and its pose are dropped).
    void setChain(const KinematicChain &chain);

    Subject subject() const;
    void setSubject(Subject subject);

    /// The analysis on display (valid == false before the first one).
    const MobilityReport &report() const { return m_shown.report; }
    /// The chain of the analysis on display.
    const KinematicChain &shownChain() const { return m_shown.chain; }
    /// The subject of the analysis on display.
    Subject shownSubject() const { return m_shown.subject; }
    /// An analysis is running or waiting: the display may be behind the last request.
    bool isBusy() const;
    /// The plain text of one part of the display, empty when that part is not shown.
    QString partText(Part part) const;
    /// The whole display as plain text.
    QString plainText() const;
    QComboBox *subjectBox() const { return m_subjectBox; }
    QTextBrowser *browser() const { return m_browser; }

signals:
    /// A new analysis is on display.
    void analysisShown();

protected:
    void showEvent(QShowEvent *event) override;
    bool event(QEvent *event) override;
    /// On a change of language: the controls' texts again, and the analysis run again (its
    /// chain and verdict are core's sentences, made in the language of the moment).
    void changeEvent(QEvent *event) override;

private:
    /// One analysis: what was asked and what came out.
    struct Analysis {
        KinematicChain chain;
        Subject subject = Subject::ThisMechanism;
        std::string kind; ///< the mechanism's kind ("oxglide"), empty for a bare chain or an example
        quint64 request = 0; ///< increases with every request
        quint64 context = 0; ///< changes with the subject or the design, not with the pose
        MobilityReport report;
    };

    /// Seen: visible, and in front in its dock's tabs.
    bool isSeen() const;
    /// Follows the dock holding the panel: a tab behind another is visible to Qt but not seen.
    void findDock();
    /// The subject or its chain changed: analyse it (when seen) or remember to.
    void request();
    void start(Analysis analysis);
    void onFinished();
    void display(const Analysis &analysis);
    void showPlaceholder(const QString &text);
    void retranslate();

    QLabel *m_subjectLabel = nullptr;
    QComboBox *m_subjectBox = nullptr;
    QTextBrowser *m_browser = nullptr;
    MechanismPtr m_mechanism;
    std::optional<Pose> m_pose;
    std::optional<KinematicChain> m_chain; ///< set by setChain()
    quint64 m_requests = 0;
    quint64 m_context = 0;
    bool m_stale = false; ///< a request came while the panel was not seen
    QPointer<QDockWidget> m_dock; ///< the dock holding the panel, if any
    bool m_dockInFront = true; ///< the dock's last visibilityChanged()
    std::optional<Analysis> m_waiting; ///< the request to start when the running one ends
    quint64 m_running = 0; ///< the request running, 0 for none
    Analysis m_shown;
    QString m_html; ///< on display
    std::map<Part, QString> m_parts; ///< plain text of the parts on display
    QThreadPool m_pool; ///< one thread: one analysis at a time (destroyed after the watcher)
    QFutureWatcher<Analysis> m_watcher;
};

} // namespace pkm
