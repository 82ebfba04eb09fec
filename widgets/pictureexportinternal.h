// What the picture export's files share: the export (pictureexport.cpp) and its dialog
// (picturedialog.cpp) write counts of pixels alike and remember what the dialog offered last.
#pragma once

#include <QSize>
#include <QString>

namespace pkm::pictureexport {

/// A count of pixels or dots for people: the locale's digits, no group separator ("1920").
QString count(int value);

/// What the picture dialog offered last time, for the next one.
struct DialogMemory {
    int preset = 0;
    QSize custom {1600, 1200};
    int dpi = 96;
};
DialogMemory &memory();

} // namespace pkm::pictureexport
