#pragma once
/// The right-hand panel for the planar four-bar (the four-bar and mobility document; docs/mathematics.md): a slider and a spin
/// box for each link length (a drag is one undo step; a length that cannot close the loop is
/// refused with the core's reason and the controls go back), Grashof's class in words with
/// s + l against p + q, the assembly range of α (and why α stops at a limit), the
/// transmission angle γ with its warning band, and the plots of figs. 4–6 (FourBarPlots).

#include "kinds/kindpanel.h"

#include <QPointer>

#include <array>

class QDoubleSpinBox;
class QGroupBox;
class QLabel;
class QSlider;

namespace pkm {

class GridReflow;

class Document;
class FourBarPlots;
class TransmissionGauge;

class FourBarPanel : public KindPanel
{
    Q_OBJECT

public:
    explicit FourBarPanel(Document *document, QWidget *parent = nullptr);

    /// A new design (the pose is the document's).
    void setDesign(const MechanismPtr &mechanism, const QString &title = {}) override;
    void setPose(const Pose &pose) override;
    /// Presenting: the plots alone, without the lengths, Grashof's class and the γ gauge.
    void setPresenting(bool on) override;

    /// The links, in the order of the sliders: "AB", "BC", "CD", "AD".
    static constexpr std::array<const char *, 4> linkNames = {"AB", "BC", "CD", "AD"};
    /// Slider steps per millimetre.
    static constexpr int sliderScale = 10;

    QSlider *lengthSlider(const QString &link) const;
    QDoubleSpinBox *lengthSpinBox(const QString &link) const;
    /// The inline message of a refused length (hidden when the last change succeeded).
    QLabel *linkMessage() const { return m_linkMessage; }
    QLabel *grashofLabel() const { return m_grashof; }
    QLabel *rangeLabel() const { return m_range; }
    /// Why α stops, shown while α sits at an assembly limit.
    QLabel *limitLabel() const { return m_limit; }
    QLabel *transmissionLabel() const { return m_transmission; }
    TransmissionGauge *transmissionGauge() const { return m_gauge; }
    /// Whether the current γ lies in the poor band (|γ| < 40° or > 140°).
    bool transmissionWarning() const { return m_poor; }
    FourBarPlots *plots() const { return m_plots; }

    /// Asks the document for link `link` = `value` mm; a refusal is shown and the controls
    /// go back to the design. `continuous` merges into the previous step of the same link.
    bool requestLength(const QString &link, double value, bool continuous);


protected:
    /// A new language: every text again, from the current design and pose.
    void changeEvent(QEvent *event) override;

private:
    struct LinkRow {
        QLabel *label = nullptr;
        QSlider *slider = nullptr;
        QDoubleSpinBox *spinBox = nullptr;
    };
    void retranslate();
    /// The transmission angle's group: γ in words, the gauge, the range over the motion
    /// (fourbargauge.cpp).
    QGroupBox *createTransmissionGroup(const QFont &labelFont);
    void showLengths(bool ranges);
    void showDesignInfo();
    /// The texts of the pose: γ, its warning, and why α stops.
    void showPose(const Pose &pose);
    void showLimit(const Pose &pose);
    void showLinkMessage();

    QPointer<Document> m_document;
    MechanismPtr m_mechanism;
    Pose m_pose; ///< the pose shown last
    std::array<LinkRow, 4> m_rows;
    QWidget *m_details = nullptr; ///< everything above the plots
    QGroupBox *m_linksGroup = nullptr;
    GridReflow *m_linksReflow = nullptr; ///< the link lengths two or one to a line
    GridReflow *m_infoReflow = nullptr; ///< the words beside the gauge or above it
    QGroupBox *m_transmissionGroup = nullptr;
    QLabel *m_linkMessage = nullptr;
    QString m_linkFailure; ///< the core's reason for the last refused length
    QString m_refusedLink; ///< that length, asked again for its reason in a new language
    double m_refusedValue = 0.0;
    QLabel *m_grashof = nullptr;
    QLabel *m_range = nullptr;
    QLabel *m_limit = nullptr;
    QLabel *m_transmission = nullptr;
    QLabel *m_transmissionRange = nullptr;
    TransmissionGauge *m_gauge = nullptr;
    FourBarPlots *m_plots = nullptr;
    bool m_updating = false; ///< the controls are being set from the design
    int m_dragging = -1; ///< the row whose slider is held down, or −1
    bool m_dragCommitted = false; ///< the current drag has made its undo step
    bool m_poor = false;
    double m_gammaMin = 0.0, m_gammaMax = 0.0; ///< |γ| over the motion, °
    QString m_limitText; ///< why α stops here, or empty
};

/// A bar 0°…180° for |γ|: the poor bands below 40° and above 140° shaded red, the range over
/// the motion as a strip, the current value as a needle.
class TransmissionGauge : public QWidget
{
    Q_OBJECT

public:
    explicit TransmissionGauge(QWidget *parent = nullptr);
    /// |γ| now and over the motion, °.
    void setValues(double gamma, double minimum, double maximum);
    double value() const { return m_value; }
    QSize sizeHint() const override { return {320, 50}; }
    QSize minimumSizeHint() const override { return {140, 50}; }

protected:
    void paintEvent(QPaintEvent *event) override;
    /// The tick labels follow the language's number format.
    void changeEvent(QEvent *event) override;

private:
    double m_value = 90.0, m_minimum = 90.0, m_maximum = 90.0;
};

} // namespace pkm
