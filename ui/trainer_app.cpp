#include "trainer_app.h"

#include <QApplication>
#include <QSettings>
#include <QTemporaryDir>
#include <QTimer>
#include <iostream>
#include <stdexcept>

#include "action_view.h"
#include "main_window.h"
#include "screenshot_demo.h"

namespace pat::ui {

int run_trainer(int argc, char** argv, const TrainerOptions& options) {
  QApplication app(argc, argv);
  QApplication::setOrganizationName("PianoActionTrainer");
  QApplication::setApplicationName("pianoaction");
  // a --screenshot (the README's pictures) neither reads nor changes the user's settings (the
  // last preset, the window's layout, the text size): its settings live in a folder of its own,
  // empty, removed at the end, so that every picture starts from the defaults
  QTemporaryDir screenshot_settings;
  if (!options.screenshot.empty()) {
    if (!screenshot_settings.isValid())
      throw std::runtime_error("--screenshot: cannot make a temporary folder for its settings");
    for (QSettings::Format format : {QSettings::NativeFormat, QSettings::IniFormat})
      QSettings::setPath(format, QSettings::UserScope, screenshot_settings.path());
  }
  MainWindow window;
  // the remembered larger text
  if (QSettings().value("view/large_text", false).toBool()) window.set_large_text(true);
  std::string action = options.action;
  if (!options.action_given)
    action = QSettings().value("last_preset", "grand").toString().toStdString();
  try {
    window.open_action(action);
  } catch (const std::exception&) {
    if (options.action_given) throw;
    window.open_action("grand");  // the remembered preset is gone or broken
  }
  window.view()->set_focus(options.view);
  if (options.width > 0 && options.height > 0)
    window.resize(options.width, options.height);
  else if (!options.screenshot.empty())
    window.resize(1280, 800);
  window.show();
  if (options.screenshot.empty()) {
    window.hold_at_rest();
    return app.exec();
  }

  int code = 0;
  auto* demo = new ScreenshotDemo(&window, QString::fromStdString(options.screenshot));
  QObject::connect(demo, &ScreenshotDemo::finished, &app, [&](bool ok, const QString& msg) {
    if (ok)
      std::cout << "screenshot of the " << window.model()->kind << " action"
                << (window.large_text() ? " (larger text)" : "") << " written to "
                << msg.toStdString() << "\n";
    else
      std::cerr << "pianoaction: " << msg.toStdString() << "\n";
    code = ok ? 0 : 1;
    QApplication::quit();
  });
  QTimer::singleShot(0, demo, &ScreenshotDemo::start);
  app.exec();
  return code;
}

}  // namespace pat::ui
