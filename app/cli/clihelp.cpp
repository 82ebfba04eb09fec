#include "cli/clihelp.h"

namespace pkm::cli {

namespace {

constexpr std::string_view mainHelp = R"(Usage: pkm COMMAND [ARGUMENTS]

PKM Studio without a display: evaluate designs of parallel-kinematic mechanisms from a
shell or a script.

Commands:
  list   [--json]                          the built-in presets: id, mechanism, title
  show   DESIGN [--set N=V]... [--json]    parameters (values, units, allowed ranges),
                                           pose variables and design warnings
  eval   DESIGN [--set N=V]... [--json]    solve one pose: coordinates, Jacobians,
                                           singularity class, derived quantities
  sweep  DESIGN --var N --from A --to B --steps K [--set N=V]... [--csv|--json]
                                           one row per step, the quantities of eval
  workspace DESIGN [--grid K] [--require N>=V]... [--set N=V]... [--json]
         [-o FILE.png|.svg]                reachable workspace: area, bounds, the area
                                           of every assembly/working mode, where the
                                           actuators deliver what is required
  map    DESIGN [--grid K] [--quantity det|cond|range|force_worst|…|spec|tolerance]
         [--require N>=V]... [--tol N=±V]... [--set N=V]... [--json]
         [-o FILE.png|.csv]                singularity, capability or worst-case
                                           error map over the workspace
  render DESIGN [--set N=V]... [--view 2d|3d] [--size WxH] [--camera front|top|side|iso]
         [--orthographic] [--no-caption] -o FILE.png|.svg|.pdf
                                           a picture of the mechanism in a pose: the
                                           2D drawing or the 3D model
  render DESIGN --var NAME --from A --to B --steps K [--one-way] -o FILE.gif
                                           an animated GIF of the 2D drawing as NAME
                                           moves from A to B
  render DESIGN --var NAME --from A --to B --steps K [--one-way] [--plot QUANTITY]
         -o FILE.mp4|.webm                 the same as a video: H.264 or VP9, 30
                                           frames/s, 1280x720 unless --size WxH;
                                           --plot draws QUANTITY against NAME beside it
  sheet  DESIGN [--set N=V]... [--lang CODE] -o FILE.pdf|.json|.csv
                                           the parameter sheet for building the
                                           prototype: parameters, dimensions, key
                                           poses, checks, plots, dimensioned drawing
  tolerance DESIGN --tol N=±V... [--samples N] [--seed S] [--normal] [--grid K]
         [--set N=V]... [--json]           the error at the pose from tolerances on
                                           the geometric parameters: first-order worst
                                           case, its parts, a Monte Carlo distribution
  dxf    DESIGN [--set N=V]... -o FILE.dxf
                                           the linkage drawing for CAD: AutoCAD R12
                                           DXF in mm, one layer per role

DESIGN is a preset id (see 'pkm list') or a design file (*.pkm.json).
--set NAME=VALUE (repeatable) changes a design parameter or sets a pose variable;
giving outputs (theta of the П-joint) solves the inverse problem, giving actuated
inputs (d) the direct one.

Units: mm, degrees, N, N·m, s; 'pkm show DESIGN' lists every name with its unit.
Numbers are read and written with '.' as the decimal separator whatever the locale,
with up to 15 significant digits.

Options:
  -h, --help    this help; 'pkm COMMAND --help' describes one command
  --version     the version of pkm

Exit status:
  0  success
  1  the output could not be written
  2  usage error: bad command line, unknown name, not a number, invalid parameter
     value, unreadable or damaged design file
  3  no solution: a pose out of range, unreachable or singular, an empty workspace,
     no OpenGL for a 3D picture
On an error pkm prints one sentence naming the culprit on stderr and nothing on stdout.
)";

constexpr std::string_view listHelp = R"(Usage: pkm list [--json]

Lists the built-in presets: id (usable as DESIGN), mechanism kind and title.

  --json    {"presets": [{"id", "mechanism", "title"}...],
             "mechanisms": [{"id", "title"}...]}
)";

constexpr std::string_view showHelp = R"(Usage: pkm show DESIGN [--set NAME=VALUE]... [--json]

Shows a design: every parameter with its value, unit, allowed range ('(' and ')' exclude
the bound, '[' and ']' include it) and whether it is stored or derived from the others;
the pose variables with their ranges and whether they are actuated inputs or outputs;
the quantities eval and sweep report, with units; and the design warnings.

  --set NAME=VALUE    applied first, as in 'pkm eval'
  --json              {"design", "title", "description", "mechanism", "mechanism_title",
                       "parameters", "variables", "quantities", "warnings"}; unbounded
                       limits are null
)";

constexpr std::string_view evalHelp = R"(Usage: pkm eval DESIGN [--set NAME=VALUE]... [--all-modes] [--equations] [--json]

Solves one pose of the design and prints every coordinate, the Jacobians, the singularity
class and the derived quantities, in display units.

  --set NAME=VALUE    NAME is a design parameter (applied in the order given) or a pose
                      variable (solved after all parameters: outputs by inverse
                      kinematics, actuated inputs by direct kinematics; giving both
                      kinds is an error). Without pose variables the design's stored pose
                      is used, re-solved from its outputs when a parameter changed (the
                      home pose, with a note on stderr, if that fails).
  --json              {"mechanism", "parameters", "pose", "jacobian", "singularity",
                       "derived", "mobility"}; a matrix is a row-major nested array;
                       singularity is {"type": none|inverse|direct|combined, "margin",
                       "undefined", "infinite", "reason"}; a quantity that is not finite at
                       the pose (J_inv at a singular pose) is null and named in
                       singularity.undefined, and in singularity.infinite too when it is
                       unbounded there (∞) rather than undefined; "reason" says why (null at
                       a regular pose); at a pose classified singular the values are exact
                       (det J = 0 at a direct singularity, never 1e13 beside one); mobility
                       counts the mechanism's freedoms by Chebyshev's and Somov–Malyshev's
                       formulas and by the rank of its loop equations; "capability" is what
                       the actuators deliver at the pose: force_worst, force_best,
                       speed_worst, speed_best, resolution_worst, stiffness (K = Jᵀ·K_q·J),
                       stiffness_worst (and the П-joint's stiffness_measured), the
                       exact velocity_polygon and force_polygon of a platform point
                       ([x, y] vertices in mm/s and N), with its own "undefined" and
                       "infinite" lists (0 or ∞ at a singular pose, why:
                       singularity.reason)
  --all-modes         also every real assembly mode at the pose's inputs (every solution
                      of the direct kinematics in the design's working modes, the pose's
                      own marked *); with --json "assembly_modes": [{"x", "y", …}, …],
                      the outputs of each in display units
  --equations         also the mechanism's governing equations with the source documents'
                      equation numbers, each with the pose's numbers put in and its result,
                      and a note where the program departs from the printed formula (as
                      the GUI's Equations panel); with --json "equations": [{"title",
                      "symbolic", "substituted", "result", "unit", "source", "note"}, …],
                      "result" in display units and null where it is not finite (∞ or —)
)";

constexpr std::string_view sweepHelp
    = R"(Usage: pkm sweep DESIGN --var NAME --from A --to B --steps K [--set NAME=VALUE]...
                 [--csv|--json]

Evaluates the design at K values of NAME and prints one row per step with the quantities
of 'pkm eval'. NAME is a pose variable (theta or d of the П-joint) or a design parameter;
A and B are in its display unit (see 'pkm show DESIGN').

  --var NAME          the quantity to sweep
  --from A, --to B    the first and the last value (A > B sweeps downwards)
  --steps K           the number of rows: K >= 2 spaces them evenly from A to B
                      inclusive, K = 1 evaluates A alone
  --set NAME=VALUE    applied before the sweep, as in 'pkm eval'
  --csv               comma-separated values with one header line (the default)
  --json              {"mechanism", "parameters", "sweep", "rows": [...]}, each row with
                      "pose", "jacobian", "singularity", "derived", "capability" as in
                      'pkm eval --json'

Each step starts from the previous step's pose, so the mechanism keeps its assembly mode.
Sweeping a pose variable keeps the design fixed; sweeping a parameter re-solves the pose
(from the --set pose variables, else from the stored pose's outputs) for every design and
adds all parameters to each row.

CSV columns, named as the keys of 'pkm eval --json': pose, jacobian, singularity (its
type), singularity_margin, derived, capability (a name that is also a parameter's, as
the П-joint's stiffness in a parameter sweep, gets the prefix "capability."); a matrix M
gives columns M[i][j] (0-based,
row-major). A value that is not finite (J_inv at a singular pose) is an empty field in CSV
and null in JSON.

Every step is solved before anything is printed: if one cannot be solved (out of range,
unreachable, singular) pkm prints nothing on stdout, names the first failing value on
stderr and exits with status 3 (2 for an invalid parameter value). 'pkm show DESIGN' gives
the ranges.
)";

constexpr std::string_view workspaceHelp
    = R"(Usage: pkm workspace DESIGN [--grid K] [--require NAME>=VALUE]... [--set NAME=VALUE]... [--json]
                     [-o FILE.png|FILE.svg]

Computes the reachable workspace of a mechanism whose output is a point of the plane (MOMA's
platform, the O-X glide's platform centre): every cell of a grid of square cells over the
workspace bounds that the design reaches in its current working and assembly modes, with
every actuated input inside its range. Prints the area (mm²), the bounds of the reachable
cells, the grid and the time, the area of every combination of the design's ±1 mode
parameters (MOMA: branch1, branch2, assembly; O-X glide: mode O or X) and the area of their
union; a combination that has no workspace has area 0 and a note. For the O-X glide, whose
planar mechanism rides the z axis, also the volume: the area extruded over the z travel.

  --grid K            K cells along the longer side of the workspace bounds, from 10 to
                      4000 (default 400); a finer grid follows the boundary more closely
  --set NAME=VALUE    applied first, as in 'pkm eval' (gamma1=-3, l1=200, assembly=1)
  --require N>=V      what the actuators must deliver (repeatable; also N<=V): a single
                      value of eval's "capability" group in its display unit, such as
                      force_worst>=50 (N), speed_worst>=100 (mm/s), resolution_worst<=0.01
                      (mm), stiffness_worst>=500 (N/mm). Adds the specification: the area
                      where every requirement holds, its share of the workspace and how many
                      cells fail each one ("specification" in JSON); with --require, -o
                      FILE.png shows that region dark in the light workspace. Without it, the
                      design file's "requirements" are used, if it states any.
  --json              {"design", "mechanism", "parameters", "area", "bounds": {"x_min",
                       "x_max", "y_min", "y_max"}, "grid": {"resolution", "columns", "rows",
                       "x_min", "x_max", "y_min", "y_max"}, "cell_size", "reachable_cells",
                       "area_union", "modes": [{MODE: -1|1..., "area", "reachable_cells",
                       "current", "note"}...], "exact_areas", "seconds"}; "area" is the
                      design's own (current modes), counted on the grid — or, where it is
                      known in closed form (the O-X glide's "area", "area_O", "area_X"),
                      the exact area, with the grid's count as "area_grid", "area_O_grid",
                      "area_X_grid"; "exact_areas" lists the closed-form areas, null where
                      none is; the O-X glide adds "area_O", "area_X", "travel", "volume"
                      and "volume_union" (mm³)
  -o FILE.png         a picture of the workspace of the current modes: the reachable cells
                      light blue on white with a dark outline, y up, at least 400 pixels;
                      for a mechanism with named modes (the O-X glide's O and X) every
                      mode's workspace over each other, larger ones first, the design's own
                      darker, their union outlined (the document's fig. 5)
  -o FILE.svg         its outline as SVG paths, in mm (viewBox), y up
                      (-o FILE and --output FILE are the same)

The file is written completely or not at all (a temporary file renamed at the end), before
anything is printed. An empty workspace (no reachable cell) exits with status 3.
)";

constexpr std::string_view mapHelp
    = R"(Usage: pkm map DESIGN [--grid K] [--quantity QUANTITY] [--require NAME>=VALUE]...
               [--tol NAME=±VALUE]... [--set NAME=VALUE]... [--json] [-o FILE.png|FILE.csv]

Computes a singularity map over the workspace of a mechanism whose output is a point of the
plane, on a grid of square cells over the workspace bounds (the design's current modes),
and prints a summary: the grid, the bounds of the reachable cells, their number, the least
and the greatest finite value, the number of near-singular cells (singularity margin below
0.05, about 3° from a singular pose) and the time.

  --grid K            K cells along the longer side of the workspace bounds, from 10 to
                      4000 (default 400)
  --quantity det      det J (the default): 0 at a direct singularity, ±∞ at an inverse one
  --quantity cond     the condition number of J (>= 1, ∞ at any singularity)
  --quantity range    a platform that turns (3-DOF planar-parallel): at each (x, y) the
                      total width of the angles φ at which it can be held, in degrees
  --quantity force_worst|speed_worst|resolution_worst|stiffness_worst
                      what the actuators deliver at each cell, as 'pkm eval' gives it in
                      its "capability" group (N, mm/s, mm, N/mm), at about the cost of
                      det J; 0 or ∞ exactly at a singularity
  --quantity spec     1 where every requirement holds, 0 where one fails (the default
                      with --require); the requirements of --require, else the design
                      file's
  --quantity tolerance
                      the first-order worst-case error of the platform point (mm) from the
                      tolerances, as 'pkm tolerance' gives it at a pose (the default with
                      --tol); the design file's tolerances, then --tol; ∞ at a direct
                      singularity; at most 400 cells a side
  --require N>=V      a requirement, as in 'pkm workspace'; repeatable
  --tol NAME=±VALUE   a tolerance, as in 'pkm tolerance'; repeatable
  --set NAME=VALUE    applied first, as in 'pkm eval'
  --json              {"design", "mechanism", "parameters", "quantity", "unit" (of a
                       capability map), "grid":
                       {"resolution", "columns", "rows", "x_min", "x_max", "y_min",
                       "y_max"}, "cell_size", "bounds", "reachable_cells", "area", "min",
                       "max", "near_singular_cells", "near_singular_margin",
                       "specification" (with spec: as 'pkm workspace --require'),
                       "tolerances" (with tolerance: NAME: VALUE in the display unit),
                       "colour_scale" (with -o FILE.png), "seconds"}
  -o FILE.png         the map as a picture, one pixel per cell, y up, unreachable cells
                      transparent; det J blue (< 0) – white (0) – red (> 0), clipped at the
                      95th percentile of |det J|; the condition number on a log scale from 1
                      (dark) to 100 (yellow); what the actuators deliver from 0 (dark) to
                      its 95th percentile (yellow), the worst-case error alike; the
                      specification green where met
  -o FILE.csv         the full map: a header line x,y,value,margin and one row per reachable
                      cell (mm, from the bottom row up); a value that is not finite (det J
                      at an inverse singularity) is an empty field
                      (-o FILE and --output FILE are the same)

The file is written completely or not at all (a temporary file renamed at the end), before
anything is printed. A map without a reachable cell exits with status 3.
)";

constexpr std::string_view renderHelp = R"(Usage: pkm render DESIGN [--set NAME=VALUE]... [--view 2d|3d] [--size WxH]
                  [--camera front|top|side|iso] [--orthographic] [--no-caption]
                  -o FILE.png|FILE.svg|FILE.pdf
       pkm render DESIGN [--set NAME=VALUE]... --var NAME --from A --to B --steps K
                  [--one-way] [--size WxH] [--no-caption] [--plot QUANTITY]
                  -o FILE.gif|FILE.mp4|FILE.webm

Draws the mechanism in a pose — the design's stored pose, or the one the --set values
give — and writes the picture to FILE. The 2D drawing is fitted to the range of motion, so
pictures of several poses of one design line up; the 3D model is fitted in its pose. A caption at the bottom-left names the
design and the pose (every pose variable in its display unit); a scale bar sits at the
bottom-right.

  --set NAME=VALUE    applied first, as in 'pkm eval' (theta=30, d=200, mode=X)
  --view 2d           the drawing of the mechanism plane, as in PKM Studio's 2D view:
                      light background, mm grid, links, joints, actuators, guides,
                      angles and dimensions (the default)
  --view 3d           the solid model, as in PKM Studio's 3D view, rendered with OpenGL
  --size WxH          the picture in pixels, whole numbers from 16 to 8000 per side
                      (default 1600x1200); SVG and PDF keep its proportions
  --camera VIEW       3D only: front (the 2D view's direction), top, side or iso
                      (isometric, the default), fitted to the model
  --orthographic      3D only: parallel projection (default: perspective)
  --no-caption        no caption line
  -o FILE.png         a raster picture of WxH pixels
  -o FILE.svg         2D: vector drawing with a WxH viewBox (text as SVG text);
                      3D: the WxH picture embedded in an SVG
  -o FILE.pdf         one page with the picture's proportions, 297 mm along the
                      longer side (A4's length): 2D as vectors, 3D the WxH picture
                      (-o FILE and --output FILE are the same)

An animation for slides and lectures: -o FILE.gif with --var NAME (a pose variable,
e.g. theta, alpha, x), --from A and --to B (display units) and --steps K (2 to 1000
frames) draws the 2D picture at K evenly spaced values, each pose solved from the one
before so the mechanism stays in its mode, 50 ms per frame, looping; it plays back to A
unless --one-way (for a crank that turns fully). Default size 960x720. A value without
a pose stops it with status 3, naming the frame.

A video: -o FILE.mp4 (H.264, yuv420p) or -o FILE.webm (VP9, or VP8 where libvpx has no
VP9) with the same options draws the same frames, one per step, at 30 frames/s: --steps 90
--one-way is 3 seconds. Default size 1280x720 (--size 1920x1080 for full HD); a video's
sides are even, 32 to 3840 wide and 32 to 2160 high. Each frame is encoded as soon as it is
drawn. An encoder that cannot be started or a full disk exits with status 1, no file left.

--plot QUANTITY (a scalar of 'pkm eval --json': d, torque, det_J…) puts QUANTITY against
NAME beside the mechanism in each frame (default size 1280x720), with a cursor and its value
at the pose: ∞ or — where a singular pose leaves it infinite or undefined.

Prints one line: Wrote FILE, with the size and the view. The file is written completely
or not at all (a temporary file renamed at the end); on an error nothing is written and
an existing FILE is left as it was. A pose that cannot be solved exits with status 3, as
in 'pkm eval'.

No display is needed. 2D pictures are drawn on Qt's offscreen platform (unless
QT_QPA_PLATFORM says otherwise). 3D pictures need OpenGL 3.3: with a display (DISPLAY or
WAYLAND_DISPLAY) it is used; without one, or when it offers no OpenGL, pkm runs the same
command again under 'xvfb-run' (Debian package xvfb, with Mesa's libgl1-mesa-dri), a
virtual X server, which adds a few tenths of a second. When OpenGL cannot be had at all pkm says why
and exits with status 3. Qt's own diagnostics are kept off stderr; PKM_QT_MESSAGES=1
shows them.
)";

constexpr std::string_view dxfHelp = R"(Usage: pkm dxf DESIGN [--set NAME=VALUE]... -o FILE.dxf

Writes the linkage drawing of the design in a pose — the design's stored pose, or the one
the --set values give — as a DXF file for CAD programs: AutoCAD R12 (AC1009) ASCII DXF,
the oldest common version, which CAD programs generally import. The drawing is what the 2D view
shows, as CAD geometry in mm, y up, in the mechanism's own frame: a joint at (x, y) in
'pkm eval' is a pin circle at (x, y) in the file, and every link's centre line is exactly as
long as the link.

Layers (AutoCAD colour index):
  GROUND (8)       the frame: ground links, the ground symbol under each ground pivot
  LINKS (5)        each link as a LINE from joint to joint and its outline
  ACTUATORS (30)   motor body, screw and axis of each linear actuator
  GUIDES (4)       rails: axis, edges, end stops, hatching on the ground side
  JOINTS (250)     pin circles, slider carriages, marked points
  DIMENSIONS (3)   dimension lines with extension lines, arrowheads and the measured
                   length ("a = 170.00", mm, 2 decimals); angle arcs with their values
  TEXT (7)         names of joints, links and guides; a caption with the design and pose
  PATHS (1)        coupler curves and trajectories, as polylines

  --set NAME=VALUE    applied first, as in 'pkm eval' (theta=30, d=200, mode=X)
  -o FILE.dxf         the file to write (-o FILE and --output FILE are the same)

Text is ASCII: Greek, Cyrillic and subscripts are written as AutoCAD's \U+XXXX escapes
(θ is \U+03B8), the degree sign as %%d. Prints one line: Wrote FILE, with the number of
entities and the drawing's size. The file is written completely or not at all (a temporary
file renamed at the end); on an error nothing is written and an existing FILE is left as it
was. A pose that cannot be solved exits with status 3, as in 'pkm eval'.
)";

constexpr std::string_view sheetHelp = R"(Usage: pkm sheet DESIGN [--set NAME=VALUE]... [--lang CODE] -o FILE.pdf|FILE.json|FILE.csv

Writes the parameter sheet of the design in a pose — the design's stored pose, or the one
the --set values give — for the workshop that builds the prototype. Its sections:

  parameters   every design parameter with its value, unit and key
  dimensions   the links between joint centres and the guides (lengths in mm), and the
               mechanism's derived dimensions (the П-joint: d_min, d_max, stroke, the
               recommended range, the free screw length, motor steps, speed and torque;
               the four-bar: its Grashof class)
  ranges       every pose variable: input or output, value in this pose, min, max, travel
  key_poses    a table of poses (the П-joint: θ_min, θ = 0, θ_max and the recommended
               range with d, φ, μ, J, T, θ̇, Δθ; the four-bar: the crank at 0°, 90°, 180°,
               270° and the least transmission angle; any mechanism: home, this pose and
               each input at the ends of its range)
  checks       PASS/FAIL against stated criteria (the П-joint's actuator check: motor
               body, torque, speed and resolution over the range, singular poses; the
               four-bar's transmission angle >= 40°; the strokes the workspace uses and
               the singular curves inside it), with INFO lines
  capability   what the actuators deliver at the pose: force, speed, resolution and
               stiffness in the weakest and strongest direction (the П-joint also its
               measured stiffness and what the two say together)
  workspace    mechanisms whose output is a point of the plane: the area as 'pkm
               workspace' computes it (grid 400; the O-X glide's areas also exact: area_O,
               area_X), per mode, its bounds, and the pictures of 'pkm workspace -o' and
               'pkm map -o'
  singular     the singular curves inside the workspace, each with one of its poses
  plots        the П-joint's d, μ, J, T, θ̇ and Δθ over θ (the document's figs. 8–17);
               the four-bar's δ, μ, ω₃, ε₃ over α; the outputs of any one-input mechanism
  drawing      the mechanism with its dimensions at a standard scale (1:2, 1:5 …) on A4
  warnings     the design warnings

  --set NAME=VALUE    applied first, as in 'pkm eval' (theta=30, a=180, mode=X)
  --lang CODE         the sheet's language: en (English, the default), sr (Serbian,
                      Cyrillic), sr_Latn (Serbian, Latin) or ru (Russian): titles,
                      labels, sentences, units and plots in that language, and the PDF's
                      numbers as it writes them (116,20 in Serbian and Russian). The JSON
                      and CSV keep their keys, PASS/FAIL/INFO, unit symbols and numbers as
                      in English; only their texts for people are translated
  -o FILE.pdf         A4 portrait pages: a title block, the sections with aligned tables,
                      the plots as vectors, the drawing with its title block; text is
                      real text, every page numbered
  -o FILE.json        the same content by key: {"sheet", "design", "title", "description",
                      "mechanism", "mechanism_title", "date", "version", "pose",
                      "sections": {KEY: {"title", "intro", "values": {KEY: {"symbol",
                      "label", "value", "unit", "decimals", "group"}}, "tables": {KEY:
                      {"title", "label_title", "columns": [{"key", "title", "unit"}],
                      "rows": [{"key", "label", "values": {COLUMN: VALUE}}], "note"}},
                      "checks": {KEY: {"title", "criterion", "value", "limit", "unit",
                      "result": PASS|FAIL|INFO, "detail"}}, "figures": [{"key", "kind",
                      "title", "caption"}], "notes": [...]}}}
  -o FILE.csv         the same values, one per line under the header
                      section,table,row,column,value,unit: the title block as
                      sheet,,KEY,value,TEXT; a value as SECTION,values,KEY,value,NUMBER,UNIT;
                      a table cell as SECTION,TABLE,ROW,COLUMN,VALUE,UNIT; a check as
                      SECTION,checks,KEY,value|limit|result,VALUE,UNIT; figures and notes as
                      SECTION,figures,KEY,title,TEXT and SECTION,notes,N,text,TEXT
                      (-o FILE and --output FILE are the same)

Numbers are in display units (mm, °, N, N·m, s): in JSON and CSV with up to 15
significant digits and '.' whatever the locale, as in 'pkm eval --json'; the PDF prints
each with its parameter's decimals, as the --lang language writes numbers. A value that
is not finite is null in JSON and an empty field in CSV. The date is today's, or that of
SOURCE_DATE_EPOCH when it is set.

Prints one line: Wrote FILE. The file is written completely or not at all (a temporary
file renamed at the end); on an error nothing is written and an existing FILE is left as
it was. No display is needed: the PDF is drawn on Qt's offscreen platform.
)";

} // namespace

std::string_view dxfHelpText()
{
    return dxfHelp;
}

constexpr std::string_view toleranceHelp
    = R"(Usage: pkm tolerance DESIGN --tol NAME=±VALUE [--tol NAME=±VALUE]... [--samples N] [--seed S]
                      [--normal] [--grid K] [--set NAME=VALUE]... [--json]

How far the platform (or the output link) is off at the pose when geometric design parameters
(lengths, positions, angles: the 'geometry' group of 'pkm show') are off by up to ±VALUE each
while the actuators hold their inputs. Prints the first-order worst case of each output
(Σ |∂x/∂p|·tol), the bound on the position error |Δx| and each parameter's part of it (which
tolerance dominates), then a Monte Carlo distribution: N designs drawn within the tolerances,
each solved at the pose's inputs in its assembly mode.

  --tol NAME=±VALUE   a tolerance, in the display unit of that parameter (mm, degrees);
                      "±0.05", "+-0.05" and "0.05" are the same; 0 removes one the design
                      file gives (its "tolerances")
  --samples N         Monte Carlo samples, 0 (first order only) to 100000 (default 2000)
  --seed S            the seed of the generator (std::mt19937_64), default 19: a seed gives
                      the same samples on every machine
  --normal            normal samples with tol = 3σ (default: uniform within ±tol)
  --grid K            also the worst case over the workspace, K cells along its longer side
                      (10 to 400; mechanisms whose output is a point of the plane)
  --set NAME=VALUE    applied first, as in 'pkm eval'
  --json              {"design", "mechanism", "parameters", "pose", "tolerances", "norm":
                       {"outputs", "unit"}, "first_order": {"method", "singularity",
                       "finite", "reason", "worst", "worst_norm", "sigma", "contributions":
                       [{"name", "tolerance", "derivative", "contribution", "share"}]},
                       "monte_carlo": {"samples", "seed", "distribution", "failed",
                       "failed_fraction", "reason", "mean", "std", "max_abs", "norm":
                       {"mean", "std", "max"}} or null, "map" (with --grid)}

At a direct singularity the first order is unbounded (∞ in the table, null with a reason in
JSON); a Monte Carlo in which no sample assembles has null statistics and a reason.
)";

std::string_view helpText(std::optional<Command> command)
{
    if (!command)
        return mainHelp;
    switch (*command) {
    case Command::List:
        return listHelp;
    case Command::Show:
        return showHelp;
    case Command::Eval:
        return evalHelp;
    case Command::Sweep:
        return sweepHelp;
    case Command::Workspace:
        return workspaceHelp;
    case Command::Map:
        return mapHelp;
    case Command::Render:
        return renderHelp;
    case Command::Sheet:
        return sheetHelp;
    case Command::Tolerance:
        return toleranceHelp;
    }
    return mainHelp;
}

} // namespace pkm::cli
