#pragma once
/// The parameter sheet of a design (`pkm sheet`, File ▸ Export Parameter Sheet…): what a
/// workshop needs to build the prototype — the design parameters with units, the derived
/// dimensions (links between joint centres, strokes), a table of key poses, the checks with
/// PASS/FAIL, the plots and a dimensioned drawing to scale.
///
/// build() makes a language-neutral model of the sheet from the Mechanism interface, so every
/// mechanism gets a sheet; the kinds the issue names add their own sections (sheetkinds.cpp):
/// the П-joint's key poses and actuator check and its plots, the four-bar's Grashof class and
/// transmission angle, the workspaces and singular poses of planar mechanisms (MOMA, the O-X
/// glide, with the O-X glide's exact areas). The model is then written as PDF (sheetpdf.cpp),
/// JSON or CSV (sheetformats.cpp) with the same content.
///
/// Keys (section, table, column, item and check keys, words such as "PASS", unit symbols) are
/// English and stable: JSON and CSV use them. Titles and labels are for people and come in the
/// current language: every English text of the sheet goes through
/// QCoreApplication::translate("Sheet", …), the labels of core's tables through coreLabel()
/// and the units through unitText(); the numbers inside sentences and in the PDF follow the
/// current locale (QLocale()). Numbers are kept at full precision in display units (mm, °, N,
/// N·m, s), written to JSON and CSV in the C locale; `decimals` says how many the PDF prints.
/// `pkm sheet --lang CODE` makes the sheet in another language (clisheet.h).
///
/// build() and the JSON and CSV writers need no QGuiApplication; the PDF needs one (fonts).

#include "capabilitymap.h"
#include "mechanism.h"

#include <Eigen/Geometry>

#include <QImage>
#include <QString>

#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

class QByteArray;

namespace pkm::sheet {

/// One value of the sheet: a number in display units or a word.
struct Cell {
    double number = std::numeric_limits<double>::quiet_NaN();
    int decimals = 2; ///< printed in the PDF with this many decimals
    std::string word; ///< a word instead of a number ("PASS", "crank-rocker"): language-neutral
    QString shown; ///< what the PDF prints when not the number or the word (a translated word)

    bool isWord() const { return !word.empty(); }
};
Cell numberCell(double value, int decimals);
Cell wordCell(std::string word, QString shown = {});
/// The text the PDF prints: the number with its decimals in the current locale ("-60.00",
/// Russian "-60,00"; "—" when not finite), or the (translated) word.
QString cellText(const Cell &cell);

/// One quantity of a key–value list.
struct Item {
    std::string key; ///< "a", "d_min"
    QString symbol; ///< "a", "d_min"
    QString label; ///< "crank (lever) length"
    Cell value;
    std::string unit; ///< display unit, "" when dimensionless
    std::string group; ///< a sub-heading key ("geometry"); empty: none
};

struct Column {
    std::string key; ///< "theta"
    QString title; ///< as printed: "θ"
    std::string unit; ///< shown in the header: "θ (°)"
    QString label; ///< what it is, for the legend below the table (may be empty)
};

struct Row {
    std::string key; ///< "theta_min"
    QString label; ///< "θ_min"
    std::vector<Cell> cells; ///< one per column
    bool highlight = false; ///< the sheet's pose
};

struct Table {
    std::string key;
    QString title;
    QString labelTitle; ///< the header of the row labels ("pose")
    std::vector<Column> columns;
    std::vector<Row> rows;
    QString note; ///< printed below the table
};

enum class Verdict { Pass, Fail, Info };
/// "PASS", "FAIL", "INFO": the language-neutral word.
const char *verdictWord(Verdict verdict);

/// A check of the design against a stated criterion.
struct Check {
    std::string key; ///< "motor_fits"
    QString title; ///< "Motor body fits the shortest diagonal"
    QString criterion; ///< "L_M < d_min"
    Cell value; ///< what the design has (the worst case over its range)
    Cell limit; ///< what the criterion allows
    std::string unit;
    Verdict verdict = Verdict::Info;
    QString detail; ///< where the worst case is, or why
};

/// A plot of curves over one variable.
struct PlotSeries {
    enum class Style { Design, Extension, Family };
    QString name;
    std::vector<std::pair<double, double>> points; ///< (x, y), display units; a NaN breaks the line
    Style style = Style::Design;
};
struct PlotBand {
    enum class Kind { Recommended, Steep };
    double from = 0.0;
    double to = 0.0;
    Kind kind = Kind::Recommended;
    QString name;
};
struct Plot {
    QString xLabel; ///< "θ (°)"
    QString yLabel; ///< "d (mm)"
    double xMin = 0.0, xMax = 1.0, yMin = 0.0, yMax = 1.0;
    std::vector<PlotSeries> series;
    std::vector<PlotBand> bands;
    std::vector<std::pair<double, QString>> levels; ///< horizontal limit lines (y) with their names
    std::optional<double> cursor; ///< x of the sheet's pose
};

enum class FigureKind { Plot, Drawing, Image };
const char *figureKindWord(FigureKind kind); ///< "plot", "drawing", "image"

struct Figure {
    std::string key;
    QString title;
    QString caption;
    FigureKind kind = FigureKind::Plot;
    Plot plot; ///< FigureKind::Plot
    Scene scene; ///< FigureKind::Drawing: drawn to a standard scale
    QImage image; ///< FigureKind::Image: a picture with y up
    /// FigureKind::Image: the image's edges in mm, for its axes (empty: none);
    /// FigureKind::Drawing: the box of the pose's drawing, mm, which the page centres
    Eigen::AlignedBox2d imageBounds;
    std::vector<std::pair<QRgb, QString>> legend; ///< colour swatches under an image
    /// FigureKind::Drawing: paper mm per mechanism mm as a standard scale, 1:2 is {1, 2}.
    std::pair<int, int> scale {1, 1};
};

/// The area of the dimensioned drawing on its A4 page, mm: the scale is the largest standard
/// one (… 1:5, 1:2, 1:1, 2:1 …) at which the mechanism's range of motion fits inside it with
/// room for the labels.
inline constexpr double drawingWidth = 174.0;
inline constexpr double drawingHeight = 214.0;
inline constexpr double drawingLabelRoom = 16.0; ///< mm of paper kept free around it for the labels
/// "1:2", "2:1", "1:1"
QString scaleText(std::pair<int, int> scale);

struct Section {
    std::string key;
    QString title;
    QString intro; ///< a sentence before the content
    std::vector<Item> items;
    std::vector<Table> tables;
    std::vector<Check> checks;
    std::vector<Figure> figures;
    std::vector<QString> notes; ///< sentences after the content
    bool newPage = false; ///< the PDF starts it on a new page
};

struct Sheet {
    std::string design; ///< the preset id or the design file's name
    QString title; ///< the design's title
    QString description;
    std::string kind; ///< "pjoint"
    QString kindTitle; ///< "Active П-joint"
    QString date; ///< ISO 8601 (SOURCE_DATE_EPOCH if set, for reproducible files)
    std::string version; ///< of PKM Studio
    QString pose; ///< "d = 183.10 mm, θ = 0.00°"
    std::vector<Section> sections;

    const Section *section(std::string_view key) const;
};

/// Where the design came from, for the title block.
struct Source {
    std::string design; ///< preset id or file name
    QString title;
    QString description;
    /// What the actuators must deliver (the design's requirements): checked at the pose and,
    /// with a planar workspace, mapped over it.
    std::vector<capability::Requirement> requirements;
};

/// Cells along the longer side of the workspace grid: `pkm workspace`'s default, so the
/// sheet's grid areas are the ones `pkm workspace --json` prints.
inline constexpr int workspaceGrid = 400;

namespace detail {
struct Parts;
}
/// The sections only one kind has (its key poses, checks, plots), which a kind's module adds to
/// the generic ones (app/kinds/kindmodule.h; kinds::buildSheet passes the right ones).
using KindSections = void (*)(const Mechanism &mechanism, const Pose &pose, detail::Parts &parts);

/// The sheet of `mechanism` at `pose` (a solved pose of it), with the sections of its kind's
/// module when given; without them, the generic sections every kind gets.
Sheet build(const Mechanism &mechanism, const Pose &pose, const Source &source, KindSections kindSections = nullptr);

// -- files ----------------------------------------------------------------------------------

enum class Format { Pdf, Json, Csv };
/// The format of a file name's extension (case-insensitive), or none.
std::optional<Format> formatOf(const std::string &path);

/// The sheet as one JSON object (UTF-8, numbers in the C locale, full precision).
std::string toJson(const Sheet &sheet);
/// The sheet as CSV: the header "section,table,row,column,value,unit" and one line per value
/// (see the help of `pkm sheet`).
std::string toCsv(const Sheet &sheet);
/// The sheet as an A4 PDF; empty with `error` set when it cannot be drawn. Needs a
/// QGuiApplication.
QByteArray toPdf(const Sheet &sheet, QString *error = nullptr);

/// Writes the sheet to `path` in the format of its extension, atomically (files::saveFile):
/// the failure is one sentence naming the file; nothing is written then.
std::optional<std::string> save(const Sheet &sheet, const std::string &path);

} // namespace pkm::sheet
