#include "commands.h"

#include "document.h"

#include <QCoreApplication>

namespace pkm {

ReplaceDesignCommand::ReplaceDesignCommand(Document *document, Design before, Design after, const QString &text)
    : QUndoCommand(text)
    , m_document(document)
    , m_before(std::move(before))
    , m_after(std::move(after))
{
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
    setText(QCoreApplication::translate("pkm::SetParameterCommand", "Change %1").arg(name));
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

} // namespace pkm
