// The thread pool the window's background work runs on (analyses, automatic regulation, the
// deregulation demo, practice tests), apart from Qt's global pool: Qt 6.4's raster engine splits
// large image conversions over the global pool and waits for them while painting, so a long
// simulation holding a global-pool thread would stall the window's paints.
#pragma once

class QThreadPool;

namespace pat::ui {

/// As many threads as cores; created on first use, lives as long as the program.
QThreadPool* background_pool();

}  // namespace pat::ui
