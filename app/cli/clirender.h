#pragma once
/// `pkm render`: a picture of the mechanism in a pose (docs/cli.md).
///
/// --view 2d (the default) draws Mechanism::scene() with the GUI's ScenePainter — background,
/// mm grid, the mechanism, the scale bar and a caption naming the design and the pose — into a
/// QImage (PNG), a QSvgGenerator (SVG) or a QPdfWriter (vector PDF). It needs a
/// QGuiApplication but no display: `pkm` runs it on the offscreen platform.
///
/// --view 3d renders Mechanism::scene3d() with Renderer3D::renderOffscreen() from a standard
/// camera fitted to the model; SVG and PDF embed that picture. OpenGL needs a display: without
/// one (or on a platform without OpenGL) `pkm` runs the same command again under xvfb-run, a
/// virtual X server, and passes its output, messages and exit status on.
///
/// Files are written completely or not at all (cli.h: saveFile), before anything is printed.

#include "cli/cliarguments.h"
#include "cli/clidesign.h"

#include <QString>
#include <QStringList>

#include <cstdio>
#include <string>
#include <vector>

namespace pkm::cli {

/// Runs `pkm render` on `prepared`: the exit status, with one sentence on `err` on failure and
/// nothing on `out` unless the file was written. Needs a QGuiApplication to draw; a 3D picture
/// without OpenGL here is rendered under Xvfb when enableXvfbRerun() was called, else fails
/// with status 3.
int runRenderCommand(const PreparedDesign &prepared, const Invocation &invocation, std::FILE *out, std::FILE *err);

/// `pkm render … --var N --from A --to B --steps K -o FILE.gif|.mp4|.webm`: the 2D picture of
/// every step, as an animated GIF or a video (clirenderanimation.cpp); runRenderCommand()'s
/// part for those files.
int runRenderAnimation(const PreparedDesign &prepared, const Invocation &invocation, std::FILE *out, std::FILE *err);

/// What main() of `pkm` must set up before its application object exists.
struct RenderSetup {
    bool guiApplication = false; ///< a QGuiApplication rather than a QCoreApplication
    bool quietQt = false; ///< drop Qt's debug, info and warning messages (one sentence on stderr)
    bool xvfbRerun = false; ///< call enableXvfbRerun() once the application exists
};

/// Looks at the command line (without the program name) and the environment: for `pkm
/// render` and `pkm sheet` (not their help, not a command line parseArguments() refuses; the
/// sheet draws its PDF as a 2D picture) it decides the Qt
/// platform and sets QT_QPA_PLATFORM — offscreen for 2D unless the user chose a platform;
/// for 3D the user's or the desktop's platform when there is a display that may offer
/// OpenGL (with Xvfb as the fallback), else none: the command then validates the design in a
/// QCoreApplication and renders under Xvfb. `pkm dxf` gets the offscreen platform too: its
/// label layout measures text. Every other command keeps a QCoreApplication.
RenderSetup prepareRenderPlatform(const std::vector<std::string> &arguments);

/// Lets runRenderCommand() re-run `program arguments` under xvfb-run when this process has no
/// OpenGL: the child gets QT_QPA_PLATFORM=xcb and PKM_RENDER_UNDER_XVFB=1 (so it never
/// re-runs itself) and its stdout, stderr and exit status become this process's.
void enableXvfbRerun(const QString &program, const QStringList &arguments);

/// The environment variable that marks the process started under Xvfb.
inline constexpr const char *underXvfbVariable = "PKM_RENDER_UNDER_XVFB";

/// The caption of a picture: "pjoint-prototype — θ = 30.00°, d = 187.13 mm" (the design's
/// file name for a design file), every pose variable in display units and the pose's words.
QString renderCaption(const PreparedDesign &prepared);
} // namespace pkm::cli
