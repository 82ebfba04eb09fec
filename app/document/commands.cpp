#include "document/commands.h"

#include "document/document.h"

#include <QCoreApplication>

namespace pkm {

void TranslatableCommand::setTextMaker(TextMaker text)
{
    m_text = std::move(text);
    retranslate();
}

void TranslatableCommand::retranslate()
{
    if (m_text)
        setText(m_text());
}

ReplaceDesignCommand::ReplaceDesignCommand(Document *document, Design before, Design after, TextMaker text)
    : m_document(document)
    , m_before(std::move(before))
    , m_after(std::move(after))
{
    setTextMaker(std::move(text));
}

void ReplaceDesignCommand::undo()
{
    m_document->applyDesign(m_before);
}

void ReplaceDesignCommand::redo()
{
    m_document->applyDesign(m_after);
}

SetParameterCommand::SetParameterCommand(Document *document, const QString &name, Design before, Design after,
                                         bool continuous)
    : m_document(document)
    , m_name(name)
    , m_continuous(continuous)
    , m_before(std::move(before))
    , m_after(std::move(after))
{
    setTextMaker([name] { return QCoreApplication::translate("pkm::SetParameterCommand", "Change %1").arg(name); });
}

void SetParameterCommand::undo()
{
    m_document->applyDesign(m_before);
}

void SetParameterCommand::redo()
{
    m_document->applyDesign(m_after);
}

bool SetParameterCommand::mergeWith(const QUndoCommand *other)
{
    const auto *next = static_cast<const SetParameterCommand *>(other);
    if (next->m_name != m_name || !next->m_continuous)
        return false;
    m_after = next->m_after;
    setObsolete(m_after.mechanism->parameters() == m_before.mechanism->parameters());
    return true;
}

SetBookmarksCommand::SetBookmarksCommand(Document *document, QList<Bookmark> before, QList<Bookmark> after,
                                         TextMaker text)
    : m_document(document)
    , m_before(std::move(before))
    , m_after(std::move(after))
{
    setTextMaker(std::move(text));
}

void SetBookmarksCommand::undo()
{
    m_document->applyBookmarks(m_before);
}

void SetBookmarksCommand::redo()
{
    m_document->applyBookmarks(m_after);
}

SetTolerancesCommand::SetTolerancesCommand(Document *document, ParameterSet before, ParameterSet after, TextMaker text)
    : m_document(document)
    , m_before(std::move(before))
    , m_after(std::move(after))
{
    setTextMaker(std::move(text));
}

void SetTolerancesCommand::undo()
{
    m_document->applyTolerances(m_before);
}

void SetTolerancesCommand::redo()
{
    m_document->applyTolerances(m_after);
}

SetRequirementsCommand::SetRequirementsCommand(Document *document, Requirements before, Requirements after,
                                               TextMaker text)
    : m_document(document)
    , m_before(std::move(before))
    , m_after(std::move(after))
{
    setTextMaker(std::move(text));
}

void SetRequirementsCommand::undo()
{
    m_document->applyRequirements(m_before);
}

void SetRequirementsCommand::redo()
{
    m_document->applyRequirements(m_after);
}

} // namespace pkm
