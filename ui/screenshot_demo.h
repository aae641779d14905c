// The --screenshot demo: strikes a blow, plays it slowed down until the hammer first comes
// within 2.5 mm of the string (the jack tripping at the let-off button, the plots showing the
// stroke), pauses there and saves the window once the regulation panel's measurements are in.
#pragma once

#include <QObject>
#include <QString>
#include <QTimer>

namespace pat::ui {

class MainWindow;

class ScreenshotDemo : public QObject {
  Q_OBJECT
 public:
  ScreenshotDemo(MainWindow* window, const QString& path);
  void start();

 signals:
  /// The screenshot was saved (ok) or could not be (message says why).
  void finished(bool ok, const QString& message);

 private:
  void poll();
  void capture();
  MainWindow* window_;
  QString path_;
  QTimer poll_timer_;
  int polls_ = 0;
};

}  // namespace pat::ui
