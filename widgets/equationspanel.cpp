#include "equationspanel.h"

#include "quantityformat.h"

#include <QEvent>
#include <QRegularExpression>
#include <QScrollBar>
#include <QTextBlock>
#include <QTextCursor>
#include <QTextDocument>

namespace pkm {

namespace {
constexpr const char *quietColour = "#5f6b7a";
constexpr const char *noteColour = "#8a5a00";

QString number(const EquationNumber &number)
{
    return formatQuantity(number.value, number.unit, number.decimals);
}

/// The text with a word joiner after each slash between terms: a unit ("рад/с"), a quotient
/// ("(a + b)/2"), a derivative ("dθ/dt", spelled out of θ̇ by symbolHtml()) stay whole.
QString slashesKept(const QString &text)
{
    static const QRegularExpression slash(QStringLiteral("(?<=[\\w)])/(?=[\\w(])"), QRegularExpression::UseUnicodePropertiesOption);
    return QString(text).replace(slash, QStringLiteral("/\u2060"));
}

/// A formula as HTML that a narrow dock wraps only after an operator, never between "sin" and
/// its angle or a number and its unit.
QString formulaText(const QString &text)
{
    const QChar keep(0x00A0);
    QString kept = text;
    kept.replace(QLatin1Char(' '), keep);
    for (const QString &op : {QStringLiteral("="), QStringLiteral("+"), QStringLiteral("−"), QStringLiteral("/")})
        kept.replace(keep + op + keep, keep + op + QLatin1Char(' '));
    // A product of numbers may break after its dot: "17879,379·17879,379·17879,379" had no
    // place to break and was cut inside a number ("17879,3" / "79"). A unit's slash may not:
    // "рад/с" broke after "рад/".
    static const QRegularExpression product(QStringLiteral("(?<=[\\d)°])·(?=[\\w(−])")); // not N·m
    kept.replace(product, QStringLiteral("·\u200B"));
    // A list may break after its separators, a matrix after its rows: the 3-RP̲R's
    // "det[(−14,92, 1,34, 0,00); (−8,19, …)]" had none and was cut inside "−8,1" / "9". A
    // decimal comma has no space after it and stays whole.
    kept.replace(QStringLiteral(",") + keep, QStringLiteral(", "));
    kept.replace(QStringLiteral(";") + keep, QStringLiteral("; "));
    // A sign before its term stays with it ("−" / "((P_i − C_i)ᵀ" was broken after the sign).
    static const QRegularExpression sign(QStringLiteral("−(?=[^\\s\\x{00A0}])"));
    kept.replace(sign, QStringLiteral("−\u2060"));
    return slashesKept(kept);
}

QString formulaHtml(const QString &text)
{
    return formulaText(text).toHtmlEscaped();
}
} // namespace

EquationsPanel::EquationsPanel(QWidget *parent)
    : QTextBrowser(parent)
{
    setOpenLinks(false);
    setFrameShape(QFrame::NoFrame);
    // the numbers are rewritten in place on every pose: no undo history may pile up
    document()->setUndoRedoEnabled(false);
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
        m_structure.clear();
        setHtml(QString());
        return;
    }
    m_equations = mechanismEquations(*m_mechanism, *m_pose);
    QString structure;
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
        structure += toQString(equation.title) + QChar(0x1F) + toQString(equation.source) + QChar(0x1F)
            + toQString(equation.symbolic) + QChar(0x1F) + toQString(equation.note) + QChar(0x1E);
    }
    if (updateNumbers(structure))
        return;

    // First, why a result can differ in its last digits from one worked out by hand.
    QString html = QStringLiteral("<p style=\"color:%1; margin-bottom:4px\">%2</p>")
                       .arg(QLatin1String(quietColour), toQString(equations::roundingNote()).toHtmlEscaped());
    std::vector<int> lineBlocks;
    int blocks = 1;
    for (std::size_t i = 0; i < m_equations.size(); ++i) {
        const Equation &equation = m_equations[i];
        // A heading begins with a capital, although the string also names a value in the values
        // panel, where Russian writes it in lower case ("якобиан ḋ = J·θ̇")
        QString title = toQString(equation.title);
        if (!title.isEmpty())
            title[0] = title[0].toUpper();
        const QString &line = m_substituted[qsizetype(i)];
        const QString &result = m_results[qsizetype(i)];
        html += QStringLiteral("<p style=\"margin-top:10px; margin-bottom:2px\"><b>%1</b> "
                               "<span style=\"color:%2; font-size:small\">— %3</span></p>")
                    .arg(slashesKept(symbolHtml(unbreakable(title))), QLatin1String(quietColour),
                         toQString(equation.source).toHtmlEscaped());
        html += QStringLiteral("<p style=\"margin-left:12px; margin-top:0px; margin-bottom:0px; font-size:large\">%1</p>")
                    .arg(symbolHtml(formulaText(toQString(equation.symbolic))));
        // the result the values panel shows, in bold, so that the eye finds it across both panels
        const qsizetype cut = line.size() - result.size();
        html += QStringLiteral("<p style=\"margin-left:24px; margin-top:0px; margin-bottom:2px; font-size:large\">%1<b>%2</b></p>")
                    .arg(formulaHtml(line.left(cut)), formulaHtml(result));
        lineBlocks.push_back(blocks + 2);
        blocks += 3;
        if (!equation.note.empty()) {
            html += QStringLiteral("<p style=\"margin-left:12px; margin-top:0px; color:%1\">%2</p>")
                        .arg(QLatin1String(noteColour), slashesKept(symbolHtml(unbreakable(toQString(equation.note)))));
            ++blocks;
        }
    }
    if (m_equations.empty())
        html = QStringLiteral("<p style=\"color:%1\">%2</p>").arg(QLatin1String(quietColour), tr("This kind lists no equations."));
    // keep the reader's place while the numbers change under a slider
    const int scroll = verticalScrollBar()->value();
    setHtml(html);
    verticalScrollBar()->setValue(scroll);
    // Later poses rewrite the lines in place, once the blocks are known to be where counted.
    m_structure.clear();
    m_lineBlocks.clear();
    bool placed = !m_equations.empty() && document()->blockCount() == blocks;
    for (std::size_t i = 0; placed && i < lineBlocks.size(); ++i)
        placed = document()->findBlockByNumber(lineBlocks[i]).text() == formulaText(m_substituted[qsizetype(i)]);
    if (placed) {
        m_structure = structure;
        m_lineBlocks = std::move(lineBlocks);
    }
}

bool EquationsPanel::updateNumbers(const QString &structure)
{
    if (m_structure.isEmpty() || structure != m_structure || m_lineBlocks.size() != m_equations.size())
        return false;
    QTextCursor edit(document());
    edit.beginEditBlock(); // one layout pass for all the lines
    for (std::size_t i = 0; i < m_lineBlocks.size(); ++i) {
        const QTextBlock block = document()->findBlockByNumber(m_lineBlocks[i]);
        const QString &line = m_substituted[qsizetype(i)];
        const QString &result = m_results[qsizetype(i)];
        // the formats the page gave the line: large, and bold for the result
        QTextCharFormat plain = block.begin().fragment().charFormat();
        plain.setFontWeight(QFont::Normal);
        QTextCharFormat bold = plain;
        bold.setFontWeight(QFont::Bold);
        QTextCursor cursor(block);
        cursor.movePosition(QTextCursor::EndOfBlock, QTextCursor::KeepAnchor);
        cursor.insertText(formulaText(line.left(line.size() - result.size())), plain);
        cursor.insertText(formulaText(result), bold);
    }
    edit.endEditBlock();
    return true;
}

} // namespace pkm
