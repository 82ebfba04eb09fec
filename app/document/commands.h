#pragma once
/// Undo commands of the document. Each stores the whole design before and after: designs are
/// small immutable values, so this is simpler and safer than inverse operations.

#include "document/designfile.h"

#include <QUndoCommand>

#include <functional>

namespace pkm {

class Document;

/// A command whose text ("Open …", "Change a") is made again in a new language
/// (Document re-texts its stack on QEvent::LanguageChange).
class TranslatableCommand : public QUndoCommand
{
public:
    using TextMaker = std::function<QString()>;
    /// Sets the text from `text` now and on every retranslate().
    void setTextMaker(TextMaker text);
    void retranslate();

private:
    TextMaker m_text;
};

/// Replaces the design (opening a preset or a file).
class ReplaceDesignCommand : public TranslatableCommand
{
public:
    /// `text` makes the command's text in the current language.
    ReplaceDesignCommand(Document *document, Design before, Design after, TextMaker text);
    void undo() override;
    void redo() override;

private:
    Document *m_document;
    Design m_before;
    Design m_after;
};

/// Changes one parameter. A stepping sequence of the same parameter (arrow keys, mouse wheel)
/// merges into one step; a merged change back to the start is obsolete and leaves the stack.
class SetParameterCommand : public TranslatableCommand
{
public:
    /// `continuous`: part of a stepping sequence (arrow keys, wheel) that merges into the
    /// previous step of the same parameter.
    SetParameterCommand(Document *document, const QString &name, Design before, Design after, bool continuous);
    void undo() override;
    void redo() override;
    int id() const override { return 1; }
    bool mergeWith(const QUndoCommand *other) override;

    const QString &name() const { return m_name; }

private:
    Document *m_document;
    QString m_name;
    bool m_continuous;
    Design m_before;
    Design m_after;
};

/// Adds or removes pose bookmarks: only the list changes, so undoing it leaves the pose and
/// the maps as they are.
class SetBookmarksCommand : public TranslatableCommand
{
public:
    SetBookmarksCommand(Document *document, QList<Bookmark> before, QList<Bookmark> after, TextMaker text);
    void undo() override;
    void redo() override;

private:
    Document *m_document;
    QList<Bookmark> m_before;
    QList<Bookmark> m_after;
};

/// Sets the design's tolerances (core/tolerance.h): only they change, so undoing it leaves the
/// pose and the maps as they are.
class SetTolerancesCommand : public TranslatableCommand
{
public:
    SetTolerancesCommand(Document *document, ParameterSet before, ParameterSet after, TextMaker text);
    void undo() override;
    void redo() override;

private:
    Document *m_document;
    ParameterSet m_before;
    ParameterSet m_after;
};

/// Sets what the actuators must deliver (core/capabilitymap.h): only the specification map and
/// its area follow.
class SetRequirementsCommand : public TranslatableCommand
{
public:
    using Requirements = std::vector<capability::Requirement>;
    SetRequirementsCommand(Document *document, Requirements before, Requirements after, TextMaker text);
    void undo() override;
    void redo() override;

private:
    Document *m_document;
    Requirements m_before;
    Requirements m_after;
};

} // namespace pkm
