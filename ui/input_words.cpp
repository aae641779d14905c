#include "input_words.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QStringList>
#include <cmath>

namespace pat::ui {
namespace {

QString tr(const char* text) {
  return QCoreApplication::translate("InputWords", text);
}

/// A number as it is shown: up to 6 decimals, without trailing zeros or an exponent ("20",
/// "0.5", "12.25", "1000").
QString shown_number(double value) {
  QString text = QString::number(value, 'f', 6);
  while (text.contains('.') && (text.endsWith('0') || text.endsWith('.'))) text.chop(1);
  return text;
}

/// A SPEC field as a number shown (shown_number); false if it is not a finite number ≥ 0, which
/// the engine refuses (the SPEC is then shown as it is).
bool field(const QStringList& fields, int i, QString& shown) {
  bool ok = false;
  const double value = fields.value(i).toDouble(&ok);
  if (!ok || !std::isfinite(value) || value < 0.0) return false;
  shown = shown_number(value);
  return true;
}

/// "a" or "an" before a number as it is read aloud: "an 8 N blow", "an 11 N blow", "an 18 kg",
/// but "a 1 kg mass", "a 110 N", "a 0.5 kg".
QString article_for(const QString& number) {
  const QString whole = number.section('.', 0, 0);
  const bool vowel = number.startsWith('8') || whole == "11" || whole == "18";
  return vowel ? QStringLiteral("an") : QStringLiteral("a");
}

/// The stroke field i of a motion SPEC ("full" when left out) in words; false for another word,
/// which the engine refuses.
bool stroke_field(const QStringList& fields, int i, QString& words) {
  if (i >= fields.size() || fields[i] == "full") {
    words = tr("full stroke");
    return true;
  }
  if (fields[i] != "half") return false;
  words = tr("half stroke, between full dip and half release");
  return true;
}

}  // namespace

QString input_in_words(const std::string& spec) {
  const QString text = QString::fromStdString(spec).trimmed();  // as the engine reads it
  if (text.isEmpty()) return tr("no finger");
  if (text.startsWith("csv:")) {
    const QString name = QFileInfo(text.mid(4)).fileName();
    return tr("the key input from %1").arg(name.isEmpty() ? text.mid(4) : name);
  }
  const QStringList f = text.split(':');
  const QString kind = f.value(0) + ':' + f.value(1);
  QString a, b, c, stroke;
  if (f.value(0) == "mass" && f.size() == 2) {
    QString value = f.value(1);
    const bool grams = value.endsWith("g") && !value.endsWith("kg");
    value.chop(grams ? 1 : 2);
    bool ok = false;
    const double kg = value.toDouble(&ok) * (grams ? 1e-3 : 1.0);
    if (ok && std::isfinite(kg) && kg > 0.0) {
      const QString shown = shown_number(kg);
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
  } else if (kind == "motion:sine" && (f.size() == 3 || f.size() == 4) && field(f, 2, a) &&
             stroke_field(f, 3, stroke)) {
    return tr("the key played %1 times a second (%2)").arg(a, stroke);
  } else if (kind == "motion:chirp" && (f.size() == 5 || f.size() == 6) && field(f, 2, a) &&
             field(f, 3, b) && field(f, 4, c) && stroke_field(f, 5, stroke)) {
    return tr("the key played ever faster, %1 to %2 times a second over %3 s (%4)")
        .arg(a, b, c, stroke);
  } else if (kind == "motion:press" && f.size() == 3 && field(f, 2, a)) {
    return tr("a slow press to the bottom in %1 s, held there").arg(a);  // "a slow": no number
  }
  return text;
}

}  // namespace pat::ui
