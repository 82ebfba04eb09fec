#include "equationspanel.h"

#include "quantityformat.h"

#include <QEvent>
#include <QScrollBar>

namespace pkm {

namespace {
constexpr const char *quietColour = "#5f6b7a";
constexpr const char *noteColour = "#8a5a00";

QString number(const EquationNumber &number)
{
    return formatQuantity(number.value, number.unit, number.decimals);
}

/// A formula as HTML that a narrow dock wraps only after an operator, never between "sin" and
/// its angle or a number and its unit.
QString formulaHtml(const QString &text)
{
    const QChar keep(0x00A0);
    QString kept = text;
    kept.replace(QLatin1Char(' '), keep);
    for (const QString &op : {QStringLiteral("="), QStringLiteral("+"), QStringLiteral("−"), QStringLiteral("/")})
        kept.replace(keep + op + keep, keep + op + QLatin1Char(' '));
    return kept.toHtmlEscaped();
}
} // namespace

EquationsPanel::EquationsPanel(QWidget *parent)
    : QTextBrowser(parent)
{
    setOpenLinks(false);
    setFrameShape(QFrame::NoFrame);
    setFocusPolicy(Qt::NoFocus);
}

void EquationsPanel::setMechanism(const MechanismPtr &mechanism)
{
    if (!m_mechanism || m_mechanism->kind() != mechanism->kind())
        m_pose.reset(); // a pose of another kind of mechanism
    m_mechanism = mechanism;
}

void EquationsPanel::setPose(const Pose &pose)
{
    m_pose = pose;
    if (!isVisible()) {
        m_stale = true;
        return;
    }
    refresh();
}

QString EquationsPanel::resultText(int index) const
{
    return index >= 0 && index < m_results.size() ? m_results[index] : QString();
}

QString EquationsPanel::substitutedText(int index) const
{
    return index >= 0 && index < m_substituted.size() ? m_substituted[index] : QString();
}

void EquationsPanel::changeEvent(QEvent *event)
{
    // the titles, sources and notes in the new language, the numbers in its locale
    if (event->type() == QEvent::LanguageChange && m_pose)
        refresh();
    QTextBrowser::changeEvent(event);
}

void EquationsPanel::showEvent(QShowEvent *event)
{
    QTextBrowser::showEvent(event);
    if (m_stale)
        refresh();
}

void EquationsPanel::refresh()
{
    m_stale = false;
    m_equations.clear();
    m_results.clear();
    m_substituted.clear();
    if (!m_mechanism || !m_pose) {
        setHtml(QString());
        return;
    }
    m_equations = mechanismEquations(*m_mechanism, *m_pose);
    QString html;
    for (const Equation &equation : m_equations) {
        const QString result = number(equation.result);
        QString line = QStringLiteral("= ");
        if (!equation.substituted.empty()) {
            line += toQString(fillEquation(equation, [](const EquationNumber &n) { return number(n).toStdString(); }))
                + QStringLiteral(" = ");
        }
        line += result;
        m_results << result;
        m_substituted << line;
        html += QStringLiteral("<p style=\"margin-top:10px; margin-bottom:2px\"><b>%1</b> "
                               "<span style=\"color:%2; font-size:small\">— %3</span></p>")
                    .arg(toQString(equation.title).toHtmlEscaped(), QLatin1String(quietColour),
                         toQString(equation.source).toHtmlEscaped());
        html += QStringLiteral("<p style=\"margin-left:12px; margin-top:0px; margin-bottom:0px; font-size:large\">%1</p>")
                    .arg(formulaHtml(toQString(equation.symbolic)));
        // the result the values panel shows, in bold, so that the eye finds it across both panels
        const qsizetype cut = line.size() - result.size();
        html += QStringLiteral("<p style=\"margin-left:24px; margin-top:0px; margin-bottom:2px; font-size:large\">%1<b>%2</b></p>")
                    .arg(formulaHtml(line.left(cut)), formulaHtml(result));
        if (!equation.note.empty()) {
            html += QStringLiteral("<p style=\"margin-left:12px; margin-top:0px; color:%1\">%2</p>")
                        .arg(QLatin1String(noteColour), toQString(equation.note).toHtmlEscaped());
        }
    }
    if (m_equations.empty())
        html = QStringLiteral("<p style=\"color:%1\">%2</p>").arg(QLatin1String(quietColour), tr("This kind lists no equations."));
    // keep the reader's place while the numbers change under a slider
    const int scroll = verticalScrollBar()->value();
    setHtml(html);
    verticalScrollBar()->setValue(scroll);
}

} // namespace pkm
