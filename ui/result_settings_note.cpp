#include "result_settings_note.h"

#include <QObject>
#include <QStringList>

#include "setting_names.h"

namespace pat::ui {
namespace {

QString parts_text(const std::vector<std::string>& removed) {
  if (removed.empty()) return QObject::tr("all parts");
  QStringList names;
  for (const std::string& part : removed) names << QString::fromStdString(part);
  return QObject::tr("without %1").arg(names.join(", "));
}

}  // namespace

QString settings_moved_note(const ActionModel& ran_on, const ActionModel& window,
                            bool settings_matter) {
  if (ran_on.kind != window.kind)
    return QObject::tr("This result is the %1's; the window shows the %2 now.")
        .arg(QString::fromStdString(ran_on.kind), QString::fromStdString(window.kind));
  if (ran_on.source_file != window.source_file)
    return QObject::tr("This result is for %1; the window shows %2 now.")
        .arg(QString::fromStdString(ran_on.source_file),
             QString::fromStdString(window.source_file));
  if (!settings_matter) return {};
  QStringList changes;
  if (ran_on.removed_parts != window.removed_parts)
    changes << QObject::tr("%1 → %2").arg(parts_text(ran_on.removed_parts),
                                          parts_text(window.removed_parts));
  for (const Adjuster& before : ran_on.adjusters) {
    for (const Adjuster& now : window.adjusters) {
      if (now.name != before.name) continue;
      // as the regulation panel shows them: a move within its last digit is not news
      const QString was = adjuster_mm_text(before.value * 1e3, 2, true);
      const QString is = adjuster_mm_text(now.value * 1e3, 2, true);
      if (was != is)
        changes << QObject::tr("%1 %2 → %3 mm").arg(setting_title(before.name), was, is);
    }
  }
  if (changes.isEmpty()) return {};
  return QObject::tr("Since this ran: %1. Press Run to see the window's settings.")
      .arg(changes.join(", "));
}

}  // namespace pat::ui
