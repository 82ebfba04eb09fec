// The П-joint plots' texts in the current language: the tabs, each plot's title, subtitle, axis
// labels and legend (the figures' numbers are the document's), set again on a change of
// language (pjointplots.cpp builds the plots).
#include "kinds/pjoint/pjointplots.h"

#include "kinds/pjoint/pjointcurves.h"
#include "plotstyle.h"

#include <qcustomplot.h>

#include <QLocale>
#include <QTabWidget>

namespace pkm {

using namespace pjointcurves;

void PJointPlots::retranslate()
{
    m_tabs->setTabText(int(Tab::Geometry), tr("Geometry"));
    m_tabs->setTabText(int(Tab::Jacobian), tr("Jacobian"));
    m_tabs->setTabText(int(Tab::Actuator), tr("Actuator"));

    const QLocale locale;
    auto number = [&](double v, int decimals) {
        return locale.toString(v, 'f', decimals).replace(QLatin1Char('-'), QChar(0x2212));
    };
    const QString a = locale.toString(m_design.a, 'g', 6);
    const QString k = number(m_design.k(), 2);
    const QString thetaMin = number(m_design.thetaMin / units::degree, 0);
    const QString thetaMax = number(m_design.thetaMax / units::degree, 0);
    const QString motorTorque = number(pjoint::motorTorque(m_design, m_design.forceMax), 3);

    const std::array<QString, PlotCount> titles {
        tr("Fig. 8 — diagonal length d(θ), (2)"),
        tr("Fig. 9 — passive angle φ(θ)"),
        tr("Fig. 10 — transmission angle μ(θ)"),
        tr("Fig. 11 — Jacobian J(θ) = ∂d/∂θ, (7)"),
        tr("Fig. 12 — inverse Jacobian J⁻¹(θ), (8)"),
        tr("Fig. 15 — output resolution Δθ = Δd/J"),
        tr("Fig. 16 — output speed θ̇ = ḋ_max/J"),
        tr("Fig. 17 — output torque T = J·F_max, (13)"),
    };
    const std::array<QString, PlotCount> subtitles {
        tr("a = %1 mm, k = %2, θ %3°…%4°; family at the same a").arg(a, k, thetaMin, thetaMax),
        tr("diagonal OA from the base OB"),
        tr("at A, diagonal to crank; J = a·sin μ"),
        tr("ḋ = J·θ̇; a = %1 mm, k = %2").arg(a, k),
        tr("θ̇ = J⁻¹·ḋ; J⁻¹ → ∞ at θ = ±90°"),
        tr("one motor step Δd = %1 mm").arg(locale.toString(m_design.step, 'g', 6)),
        tr("at the maximum linear speed ḋ_max = %1 mm/s").arg(locale.toString(m_design.speedMax, 'g', 6)),
        // (15) T_M = F·h/(2π·η) does not depend on θ: one number, not a curve.
        tr("F_max = %1 N; motor torque T_M = %2 N·m at any θ (15)")
            .arg(locale.toString(m_design.forceMax, 'g', 6), motorTorque),
    };

    // Tick labels are written in the plot widget's locale (QCustomPlot sets "C" for itself):
    // the language's, without group separators, as the numbers elsewhere.
    QLocale tickLocale = locale;
    tickLocale.setNumberOptions(locale.numberOptions() | QLocale::OmitGroupSeparator);

    for (int i = 0; i < PlotCount; ++i) {
        Panel &p = m_panels[i];
        if (p.plot->locale() != tickLocale)
            p.plot->setLocale(tickLocale);
        plotstyle::forgetLegendNames(p.plot); // the names below are new: fitToWidth() wraps them
        plotstyle::setFittedText(p.title, titles[size_t(i)]);
        plotstyle::setFittedText(p.subtitle, subtitles[size_t(i)]);
        p.plot->xAxis->setLabel(tr("θ (°)"));
        // The dot of θ̇ is lost in a rotated label at this size: spell the derivative out.
        const QString symbol = i == SpeedPlot ? tr("dθ/dt") : symbolOf(i);
        p.plot->yAxis->setLabel(tr("%1 (%2)").arg(symbol, unitOf(i)));
        p.design->setName(tr("this design (k = %1)").arg(k));
        if (p.extension)
            p.extension->setName(tr("beyond its θ range"));
        for (int j = 0; j < quantities[i].familySize; ++j)
            p.family[size_t(j)]->setName(tr("k = %1").arg(locale.toString(familyK[size_t(j)], 'f', 1)));
        if (p.recommendedSwatch) {
            const Interval recommended = pjoint::recommendedRange(m_design);
            p.recommendedSwatch->setName(tr("recommended %1°…%2° (J ≥ %3 % of best)")
                                             .arg(number(recommended.min / units::degree, 0),
                                                  number(recommended.max / units::degree, 0))
                                             .arg(locale.toString(pjoint::recommendedTorqueShare * 100)));
        }
        if (p.steepSwatch)
            p.steepSwatch->setName(tr("steep region"));
        if (p.weakTransmissionSwatch)
            p.weakTransmissionSwatch->setName(tr("μ < %1°: force almost along the crank").arg(locale.toString(weakTransmission)));
        fitToWidth(i);
    }
}

} // namespace pkm
