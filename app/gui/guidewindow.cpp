// The user guide inside the program (issue 18): Markdown rendered by QTextBrowser from the
// resources the build makes (app/gui/CMakeLists.txt), so that it works from the build folder
// and from an installed program alike, with no file to find at run time.

#include "gui/guidewindow.h"

#include "document/language.h"

#include <QDesktopServices>
#include <QEvent>
#include <QFile>
#include <QHBoxLayout>
#include <QImage>
#include <QKeySequence>
#include <QLabel>
#include <QLineEdit>
#include <QShortcut>
#include <QScrollBar>
#include <QTextBrowser>
#include <QToolButton>
#include <QVBoxLayout>

namespace pkm {

namespace {

constexpr auto guideRoot = "qrc:/guide/docs/guide/";

/// The guide's screenshots are taken on large screens: shown at their size they would push the
/// text into a horizontal scroll, so they are scaled down to a width that reads beside it.
constexpr int maximumPictureWidth = 820;

class GuideBrowser : public QTextBrowser
{
public:
    using QTextBrowser::QTextBrowser;

    QVariant loadResource(int type, const QUrl &name) override
    {
        QVariant loaded = QTextBrowser::loadResource(type, name);
        if (type != QTextDocument::ImageResource || !loaded.isValid())
            return loaded;
        QImage image = loaded.typeId() == QMetaType::QImage ? loaded.value<QImage>()
                                                           : QImage::fromData(loaded.toByteArray());
        if (image.isNull())
            return loaded;
        if (image.width() > maximumPictureWidth)
            image = image.scaledToWidth(maximumPictureWidth, Qt::SmoothTransformation);
        return image;
    }
};

} // namespace

QString guideSource(const QString &languageCode)
{
    const QString own = QString::fromLatin1(guideRoot) + QStringLiteral("guide.%1.md").arg(languageCode);
    if (QFile::exists(QStringLiteral(":") + QUrl(own).path()))
        return own;
    return QString::fromLatin1(guideRoot) + QStringLiteral("guide.en.md");
}

GuideWindow::GuideWindow(QWidget *parent)
    : QWidget(parent, Qt::Window)
{
    setObjectName(QStringLiteral("guideWindow"));
    resize(900, 680);
    m_browser = new GuideBrowser(this);
    m_browser->setObjectName(QStringLiteral("guideBrowser"));
    // Links to web pages go to the browser; links between the guide's pages stay here.
    m_browser->setOpenLinks(true);
    m_browser->setOpenExternalLinks(true);

    m_back = new QToolButton(this);
    m_home = new QToolButton(this);
    connect(m_back, &QToolButton::clicked, m_browser, &QTextBrowser::backward);
    connect(m_browser, &QTextBrowser::backwardAvailable, m_back, &QToolButton::setEnabled);
    m_back->setEnabled(false);
    connect(m_home, &QToolButton::clicked, this, &GuideWindow::reload);

    m_findLabel = new QLabel(this);
    m_find = new QLineEdit(this);
    m_find->setObjectName(QStringLiteral("guideFind"));
    m_find->setClearButtonEnabled(true);
    m_findLabel->setBuddy(m_find);
    m_previous = new QToolButton(this);
    m_next = new QToolButton(this);
    m_notFound = new QLabel(this);
    m_notFound->setStyleSheet(QStringLiteral("color: #b3261e;"));
    m_notFound->hide();
    connect(m_find, &QLineEdit::returnPressed, this, [this] { findNext(false); });
    connect(m_find, &QLineEdit::textEdited, this, [this] {
        // search as one types, from the start of the current match
        QTextCursor cursor = m_browser->textCursor();
        cursor.setPosition(cursor.selectionStart());
        m_browser->setTextCursor(cursor);
        findNext(false);
    });
    connect(m_next, &QToolButton::clicked, this, [this] { findNext(false); });
    connect(m_previous, &QToolButton::clicked, this, [this] { findNext(true); });
    auto *findShortcut = new QShortcut(QKeySequence::Find, this);
    connect(findShortcut, &QShortcut::activated, this, [this] {
        m_find->setFocus(Qt::ShortcutFocusReason);
        m_find->selectAll();
    });
    auto *nextShortcut = new QShortcut(QKeySequence::FindNext, this);
    connect(nextShortcut, &QShortcut::activated, this, [this] { findNext(false); });
    auto *previousShortcut = new QShortcut(QKeySequence::FindPrevious, this);
    connect(previousShortcut, &QShortcut::activated, this, [this] { findNext(true); });
    // Esc closes the guide, as a help window does; in the find field it first empties it.
    auto *closeShortcut = new QShortcut(QKeySequence(Qt::Key_Escape), this);
    connect(closeShortcut, &QShortcut::activated, this, [this] {
        if (m_find->hasFocus() && !m_find->text().isEmpty())
            m_find->clear();
        else
            close();
    });

    auto *bar = new QHBoxLayout;
    bar->addWidget(m_back);
    bar->addWidget(m_home);
    bar->addSpacing(12);
    bar->addWidget(m_findLabel);
    bar->addWidget(m_find, 1);
    bar->addWidget(m_previous);
    bar->addWidget(m_next);
    bar->addWidget(m_notFound);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(bar);
    layout->addWidget(m_browser, 1);

    retranslate();
    reload();
}

void GuideWindow::reload()
{
    m_loadedLanguage = language::current();
    m_browser->clearHistory();
    m_browser->setSource(QUrl(guideSource(m_loadedLanguage)), QTextDocument::MarkdownResource);
}

void GuideWindow::followLanguage()
{
    if (m_loadedLanguage != language::current())
        reload();
}

bool GuideWindow::findNext(bool backward)
{
    const QString text = m_find->text();
    m_notFound->hide();
    if (text.isEmpty())
        return false;
    const QTextDocument::FindFlags flags = backward ? QTextDocument::FindBackward : QTextDocument::FindFlags();
    bool found = m_browser->find(text, flags);
    if (!found) {
        // round the guide: from the other end once more
        QTextCursor cursor = m_browser->textCursor();
        cursor.movePosition(backward ? QTextCursor::End : QTextCursor::Start);
        m_browser->setTextCursor(cursor);
        found = m_browser->find(text, flags);
    }
    if (!found) {
        m_notFound->show();
        return false;
    }
    // The match in the middle of the page, with what leads up to it and follows: scrolled
    // only into sight, it sat on the bottom edge, its sentence cut.
    const QRect match = m_browser->cursorRect();
    const int height = m_browser->viewport()->height();
    if (match.top() < height / 4 || match.bottom() > 3 * height / 4) {
        QScrollBar *bar = m_browser->verticalScrollBar();
        bar->setValue(bar->value() + match.center().y() - height / 2);
    }
    return true;
}

void GuideWindow::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange) {
        retranslate();
        followLanguage();
    }
    QWidget::changeEvent(event);
}

void GuideWindow::retranslate()
{
    setWindowTitle(tr("PKM Studio User Guide"));
    m_back->setText(tr("Back"));
    m_home->setText(tr("Start"));
    m_home->setToolTip(tr("The start of the guide"));
    m_findLabel->setText(tr("&Find:"));
    m_find->setPlaceholderText(tr("a word in the guide (Ctrl+F)"));
    m_previous->setText(tr("Previous"));
    m_next->setText(tr("Next"));
    m_notFound->setText(tr("Not found"));
}

} // namespace pkm
