// What the main window's files share (mainwindow.cpp, mainwindowdesign.cpp, mainwindowfiles.cpp):
// a core failure's message as the status bar and the message boxes show it.
#pragma once

#include "mechanism.h"

#include <QString>

namespace pkm::mainwindow {

inline QString failureText(const Failure &failure)
{
    return QString::fromStdString(failure.message);
}

} // namespace pkm::mainwindow
