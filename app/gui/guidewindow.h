#pragma once
/// Help ▸ User Guide (F1): the user guide in a window of its own, in the chosen language where
/// a translation exists, with its pictures, working links and a find field (Ctrl+F).

#include <QString>
#include <QWidget>

class QLabel;
class QLineEdit;
class QTextBrowser;
class QToolButton;

namespace pkm {

/// Where the guide for `languageCode` (language.h) is: the resource of its own translation
/// (docs/guide/guide.<code>.md, built into the program), else the English guide, which the
/// build takes from the README's part for users.
QString guideSource(const QString &languageCode);

class GuideWindow : public QWidget
{
    Q_OBJECT

public:
    explicit GuideWindow(QWidget *parent = nullptr);

    QTextBrowser *browser() const { return m_browser; }
    QLineEdit *findField() const { return m_find; }
    /// Loads the guide of the current language (language::current()) from its start.
    void reload();
    /// Loads the guide of the current language unless it is the one shown.
    void followLanguage();
    /// Selects the next (or, `backward`, the previous) occurrence of the find field's text,
    /// round the guide; false when there is none.
    bool findNext(bool backward = false);

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslate();

    QTextBrowser *m_browser = nullptr;
    QLineEdit *m_find = nullptr;
    QLabel *m_findLabel = nullptr;
    QLabel *m_notFound = nullptr;
    QToolButton *m_back = nullptr;
    QToolButton *m_home = nullptr;
    QToolButton *m_previous = nullptr;
    QToolButton *m_next = nullptr;
    QString m_loadedLanguage;
};

} // namespace pkm
