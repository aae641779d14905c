#include "animation_export.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QImage>
#include <QStringList>
#include <QTextStream>
#include <algorithm>
#include <cmath>

#include "action_view.h"
#include "core/error.h"
#include "frame_history.h"
#include "plot_export.h"

namespace pat::ui {
namespace {

QString frame_name(int index) {
  return QStringLiteral("frame_%1.png").arg(index, 4, 10, QLatin1Char('0'));
}

std::string text(const QString& s) {
  return s.toStdString();
}

}  // namespace

std::vector<double> animation_times(const FrameHistory& history, const AnimationOptions& options) {
  if (history.empty()) throw InputError("animation: there is no recorded run to draw");
  if (!(options.interval_s > 0.0) || !std::isfinite(options.interval_s))
    throw InputError("animation: the time between pictures must be a positive number of seconds");
  const double from = std::max(options.from_s, history.first_time());
  const double to = std::min(options.to_s, history.last_time());
  if (!(to >= from))
    throw InputError("animation: the time range holds no recorded frame of the run");
  // a hair of the interval's rounding: the last picture lands on `to` when the range is a whole
  // number of intervals
  const double count = std::floor((to - from) / options.interval_s + 1e-9) + 1.0;
  if (count > kMaxAnimationFrames)
    throw InputError("animation: " + std::to_string(static_cast<long long>(count)) +
                     " pictures (more than " + std::to_string(kMaxAnimationFrames) +
                     "): show a shorter time span in the plots or choose a faster speed");
  std::vector<double> times;
  for (int i = 0; i < static_cast<int>(count); ++i) times.push_back(from + i * options.interval_s);
  return times;
}

int export_action_animation(const FrameHistory& history, const AnimationOptions& options,
                            const QString& folder,
                            const std::function<bool(int done, int total)>& progress) {
  const std::vector<double> times = animation_times(history, options);
  const QDir dir(folder);
  if (!dir.exists()) throw InputError(text(folder) + ": no such folder");
  // nothing overwritten: a folder that holds an earlier sequence is refused before anything is
  // written
  const QString table = dir.filePath("frames.csv");
  QStringList to_write{table};
  for (int i = 0; i < static_cast<int>(times.size()); ++i) to_write << dir.filePath(frame_name(i));
  for (const QString& path : to_write)
    if (QFileInfo::exists(path))
      throw InputError(text(path) +
                       ": already there (an earlier export?); choose an empty folder, nothing "
                       "was written");

  // wider than the plots' layout width, the view laid out at it and drawn larger, text included,
  // as the plot export does: at 1600 px the labels would otherwise be a slide's small print
  const double scale = std::max(1.0, options.size.width() / kExportLayoutWidth);
  ActionView view;
  view.setAttribute(Qt::WA_DontShowOnScreen);
  view.resize(QSize(static_cast<int>(std::lround(options.size.width() / scale)),
                    static_cast<int>(std::lround(options.size.height() / scale))));
  view.set_focus(options.focus);
  view.set_labels_visible(options.labels);
  view.set_measurements_visible(options.measurements);

  QFile csv(table);
  if (!csv.open(QIODevice::WriteOnly | QIODevice::Text))
    throw InputError(text(table) + ": could not write it (" + text(csv.errorString()) + ")");
  QTextStream rows(&csv);
  rows << "frame,time_s\n";
  int written = 0;
  for (const double t : times) {
    view.show_frame(history.interpolated(t));
    // drawn into an image of the size asked for (grab() would multiply it by a HiDPI screen's
    // device pixel ratio), the layout scaled up to it
    QImage picture(options.size, QImage::Format_RGB32);
    picture.setDevicePixelRatio(scale);
    picture.fill(Qt::white);
    view.render(&picture);
    picture.setDevicePixelRatio(1.0);  // saved as the pixels it has
    const QString path = dir.filePath(frame_name(written));
    if (!picture.save(path, "PNG")) throw InputError(text(path) + ": could not write the PNG");
    rows << written << ',' << QString::number(t, 'g', 10) << '\n';
    rows.flush();
    ++written;
    if (progress && !progress(written, static_cast<int>(times.size()))) break;
  }
  return written;
}

}  // namespace pat::ui
