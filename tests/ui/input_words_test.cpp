// A key input SPEC told in words (ui/input_words.h): every kind of DESIGN.md section 5, and a
// SPEC not understood shown as it is.
#include "input_words.h"

#include <QTest>

using pat::ui::input_in_words;

class InputWordsTest : public QObject {
  Q_OBJECT
 private slots:
  void every_kind_in_words() {
    QCOMPARE(input_in_words(""), QString("no finger"));
    QCOMPARE(input_in_words("mass:1kg"), QString("a 1 kg mass laid on the key"));
    QCOMPARE(input_in_words("mass:500g"), QString("a 0.5 kg mass laid on the key"));
    QCOMPARE(input_in_words("force:const:5"), QString("a steady 5 N on the key"));
    QCOMPARE(input_in_words("force:const:0"), QString("the key let go"));
    QCOMPARE(input_in_words("force:pulse:20:40"), QString("a 20 N blow held 40 ms"));
    // the article as the number is read aloud
    QCOMPARE(input_in_words("force:pulse:8:80"), QString("an 8 N blow held 80 ms"));
    QCOMPARE(input_in_words("force:pulse:11:40"), QString("an 11 N blow held 40 ms"));
    QCOMPARE(input_in_words("force:pulse:18.5:40"), QString("an 18.5 N blow held 40 ms"));
    QCOMPARE(input_in_words("force:pulse:110:40"), QString("a 110 N blow held 40 ms"));
    QCOMPARE(input_in_words("mass:0.8kg"), QString("a 0.8 kg mass laid on the key"));
    QCOMPARE(input_in_words("mass:8kg"), QString("an 8 kg mass laid on the key"));
    QCOMPARE(input_in_words("force:double:20:30:60"),
             QString("two 20 N blows held 30 ms, 60 ms apart"));
    QCOMPARE(input_in_words("motion:sine:12.5:half"),
             QString("the key played 12.5 times a second (half stroke, between full dip and "
                     "half release)"));
    QCOMPARE(input_in_words("motion:sine:3"), QString("the key played 3 times a second (full "
                                                      "stroke)"));
    QCOMPARE(input_in_words("motion:chirp:2:20:10:full"),
             QString("the key played ever faster, 2 to 20 times a second over 10 s (full "
                     "stroke)"));
    QCOMPARE(input_in_words("motion:press:1.5"),
             QString("a slow press to the bottom in 1.5 s, held there"));
    // numbers as typed, without rounding or an exponent; a SPEC trimmed as the engine reads it
    QCOMPARE(input_in_words("force:pulse:12.25:1000"), QString("a 12.25 N blow held 1000 ms"));
    QCOMPARE(input_in_words("  force:pulse:20:40 "), QString("a 20 N blow held 40 ms"));
    QCOMPARE(input_in_words("csv:/home/teacher/measured/blow 3.csv"),
             QString("the key input from blow 3.csv"));
  }

  void a_spec_not_understood_is_shown_as_it_is() {
    for (const char* spec :
         {"force:pulse:20", "force:pulse:x:40", "motion:wobble:3", "mass:lots",
          "force:double:1:2:3:4", "motion:sine:3:bogus", "motion:chirp:2:20:10:sideways",
          "force:pulse:nan:40", "force:pulse:-5:40", "force:const:inf", "mass:-1kg"})
      QCOMPARE(input_in_words(spec), QString(spec));
  }
};

QTEST_GUILESS_MAIN(InputWordsTest)
#include "input_words_test.moc"
