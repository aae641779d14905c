#include "input_words.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QStringList>

namespace pat::ui {
namespace {

QString tr(const char* text) {
  return QCoreApplication::translate("InputWords", text);
}

/// A SPEC field as a number shown to 3 significant digits ("20", "0.5", "12.5"); false if it is
/// not a number.
bool field(const QStringList& fields, int i, QString& shown) {
  bool ok = false;
  const double value = fields.value(i).toDouble(&ok);
  if (ok) shown = QString::number(value, 'g', 3);
  return ok;
}

/// "a" or "an" before a number as it is read aloud: "an 8 N blow", "an 11 N blow", "an 18 kg",
/// but "a 1 kg mass", "a 110 N", "a 0.5 kg".
QString article_for(const QString& number) {
  const QString whole = number.section('.', 0, 0);
  const bool vowel = number.startsWith('8') || whole == "11" || whole == "18";
  return vowel ? QStringLiteral("an") : QStringLiteral("a");
}

QString stroke_words(const QStringList& fields, int i) {
  return fields.value(i) == "half" ? tr("half stroke, between full dip and half release")
                                   : tr("full stroke");
}

}  // namespace

QString input_in_words(const std::string& spec) {
  const QString text = QString::fromStdString(spec);
  if (text.isEmpty()) return tr("no finger");
  if (text.startsWith("csv:")) {
    const QString name = QFileInfo(text.mid(4)).fileName();
    return tr("the key input from %1").arg(name.isEmpty() ? text.mid(4) : name);
  }
  const QStringList f = text.split(':');
  const QString kind = f.value(0) + ':' + f.value(1);
  QString a, b, c;
  if (f.value(0) == "mass" && f.size() == 2) {
    QString value = f.value(1);
    const bool grams = value.endsWith("g") && !value.endsWith("kg");
    value.chop(grams ? 1 : 2);
    bool ok = false;
    const double kg = value.toDouble(&ok) * (grams ? 1e-3 : 1.0);
    if (ok) {
      const QString shown = QString::number(kg, 'g', 3);
      return tr("%1 %2 kg mass laid on the key").arg(article_for(shown), shown);
    }
  } else if (kind == "force:const" && f.size() == 3 && field(f, 2, a)) {
    if (a == "0") return tr("the key let go");
    return tr("a steady %1 N on the key").arg(a);
  } else if (kind == "force:pulse" && f.size() == 4 && field(f, 2, a) && field(f, 3, b)) {
    return tr("%1 %2 N blow held %3 ms").arg(article_for(a), a, b);
  } else if (kind == "force:double" && f.size() == 5 && field(f, 2, a) && field(f, 3, b) &&
             field(f, 4, c)) {
    return tr("two %1 N blows held %2 ms, %3 ms apart").arg(a, b, c);
  } else if (kind == "motion:sine" && (f.size() == 3 || f.size() == 4) && field(f, 2, a)) {
    return tr("the key played %1 times a second (%2)").arg(a, stroke_words(f, 3));
  } else if (kind == "motion:chirp" && (f.size() == 5 || f.size() == 6) && field(f, 2, a) &&
             field(f, 3, b) && field(f, 4, c)) {
    return tr("the key played ever faster, %1 to %2 times a second over %3 s (%4)")
        .arg(a, b, c, stroke_words(f, 5));
  } else if (kind == "motion:press" && f.size() == 3 && field(f, 2, a)) {
    return tr("a slow press to the bottom in %1 s, held there").arg(a);  // "a slow": no number
  }
  return text;
}

}  // namespace pat::ui
