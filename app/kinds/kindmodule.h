#pragma once
/// What a mechanism kind adds to the application beyond its core module (core/kinds/<kind>/):
/// its own panel beside the linkage and its own sections of the parameter sheet. Each kind that
/// has any lives in app/kinds/<kind>/ and is listed once, in kinds.cpp; the main window, the
/// sheet and the command line ask this registry and fall back to the generic panels and
/// sections for a kind that is not in it.

#include "export/sheet.h"
#include "mechanism.h"

#include <string_view>
#include <vector>

class QWidget;

namespace pkm {

class Document;
class KindPanel;

/// A design to start from (File ▸ New from Template): a preset opened as a new design of the
/// user's own.
struct DesignTemplate {
    const char *title = nullptr;  ///< the menu's text, marked QT_TRANSLATE_NOOP("pkm::MainWindow", …)
    const char *preset = nullptr; ///< the preset id it copies
};

struct KindModule {
    std::string_view kind; ///< the core kind id ("pjoint")
    /// The panel beside the linkage, made once by the main window (nullptr: the generic one).
    KindPanel *(*createPanel)(Document *document, QWidget *parent) = nullptr;
    /// The sections of the parameter sheet only this kind has (nullptr: the generic ones).
    sheet::KindSections sheetSections = nullptr;
    /// The designs of this kind to start from, in the menu's order.
    std::vector<DesignTemplate> templates = {};
};

namespace kinds {

/// Every kind's module, in the order of kinds.cpp.
const std::vector<KindModule> &modules();
/// The module of `kind`, or nullptr for a kind with none.
const KindModule *find(std::string_view kind);
/// sheet::build() with the sections of the mechanism's kind.
sheet::Sheet buildSheet(const Mechanism &mechanism, const Pose &pose, const sheet::Source &source);

} // namespace kinds

} // namespace pkm
