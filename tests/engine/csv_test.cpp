// CSV reading and writing (io/csv.h): exact round trip, lenient layout, located errors.
#include "io/csv.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <string>

#include "core/error.h"

namespace pat {
namespace {

namespace fs = std::filesystem;

// A fresh folder under the system temporary folder, removed at the end of the test.
class CsvTest : public ::testing::Test {
 protected:
  void SetUp() override {
    std::random_device random;
    std::ostringstream name;
    name << "pat_csv_test_" << std::hex << random() << random();
    dir_ = fs::temp_directory_path() / name.str();
    fs::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }

  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  std::string write_text(const std::string& name, const std::string& text) const {
    std::ofstream out(path(name), std::ios::binary);
    out << text;
    return path(name);
  }

  static std::string read_text(const std::string& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }

  // The InputError message read_csv gives for `text`, or "" (and a failure) if none.
  std::string read_error(const std::string& text, const std::string& name = "trace.csv") const {
    const std::string file = write_text(name, text);
    try {
      read_csv(file);
    } catch (const InputError& e) {
      return e.what();
    }
    ADD_FAILURE() << "no InputError for:\n" << text;
    return "";
  }

  fs::path dir_;
};

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST_F(CsvTest, RoundTripKeepsMetadataHeaderAndExactValues) {
  CsvTable table;
  table.metadata["action"] = "grand";
  table.metadata["input"] = "force:pulse:20:5";
  table.metadata["note"] = "";  // a metadata line without a value
  table.columns = {"time_s", "key_angle_deg", "hammer_angle_deg"};
  table.rows = {
      {0.0, -0.0, 1.0 / 3.0},
      {0.1, 2.0 / 3.0, -1e-300},
      {std::nextafter(0.2, 1.0), 1e300, std::numeric_limits<double>::denorm_min()},
      {123456789.125, -std::numeric_limits<double>::max(), 3.141592653589793},
  };
  const std::string file = path("round.csv");
  write_csv(file, table);
  EXPECT_EQ(read_text(file), format_csv(table));

  const CsvTable back = read_csv(file);
  EXPECT_EQ(back.metadata, table.metadata);
  EXPECT_EQ(back.columns, table.columns);
  ASSERT_EQ(back.rows.size(), table.rows.size());
  for (std::size_t r = 0; r < table.rows.size(); ++r) {
    ASSERT_EQ(back.rows[r].size(), table.rows[r].size());
    for (std::size_t c = 0; c < table.rows[r].size(); ++c) {
      EXPECT_EQ(back.rows[r][c], table.rows[r][c]) << "row " << r << " column " << c;
      EXPECT_EQ(std::signbit(back.rows[r][c]), std::signbit(table.rows[r][c]));
    }
  }
}

TEST_F(CsvTest, FormatIsPlainAndShortest) {
  CsvTable table;
  table.metadata["action"] = "upright";
  table.metadata["flag"] = "";
  table.columns = {"time_s", "key_force_n"};
  table.rows = {{0.0, 0.1}, {0.001, 20.0}};
  EXPECT_EQ(format_csv(table), "# action: upright\n# flag\ntime_s,key_force_n\n0,0.1\n0.001,20\n");
}

TEST_F(CsvTest, WriteReplacesAnExistingFileAndLeavesNoTemporaryFile) {
  const std::string file = write_text("out.csv", "old contents\n");
  CsvTable table;
  table.columns = {"time_s"};
  table.rows = {{1.5}};
  write_csv(file, table);
  EXPECT_EQ(read_text(file), "time_s\n1.5\n");
  int entries = 0;
  for (const auto& entry : fs::directory_iterator(dir_)) {
    (void)entry;
    ++entries;
  }
  EXPECT_EQ(entries, 1);
}

TEST_F(CsvTest, WriteIntoAMissingFolderNamesThePath) {
  CsvTable table;
  table.columns = {"time_s"};
  const std::string file = path("no_such_folder/out.csv");
  try {
    write_csv(file, table);
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_TRUE(contains(e.what(), file)) << e.what();
    EXPECT_TRUE(contains(e.what(), "does not exist")) << e.what();
  }
}

// What a write would replace through its rename is checked first: a pipe or device (an --out
// of /dev/null, as root, had replaced the device with a plain file), a read-only file, a folder
// that takes no new file (checked before a command's work, so that it writes none of its other
// outputs); a link is followed, its target replaced and the link kept.
TEST_F(CsvTest, WriteRefusesPipesReadOnlyFilesAndClosedFoldersAndFollowsLinks) {
  CsvTable table;
  table.columns = {"time_s"};
  table.rows = {{2.0}};
  auto refusal = [&](const std::string& file) -> std::string {
    try {
      write_csv(file, table);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  };
  const std::string pipe = path("pipe");
  ASSERT_EQ(::mkfifo(pipe.c_str(), 0644), 0);
  EXPECT_TRUE(contains(refusal(pipe), "not a plain file")) << refusal(pipe);
  EXPECT_TRUE(fs::is_fifo(pipe));

  const std::string locked = write_text("locked.csv", "kept\n");
  fs::permissions(locked, fs::perms::owner_read | fs::perms::group_read | fs::perms::others_read);
  EXPECT_TRUE(contains(refusal(locked), "read-only")) << refusal(locked);
  EXPECT_EQ(read_text(locked), "kept\n");

  // /proc takes no new file, even for root (CI runs as root: a folder's permissions would not do)
  const std::string closed = refusal("/proc/pat_csv_test.csv");
  EXPECT_TRUE(contains(closed, "takes no new file") && contains(closed, "/proc")) << closed;

  const std::string target = write_text("target.csv", "old\n");
  const std::string link = path("link.csv");
  fs::create_symlink("target.csv", link);
  write_csv(link, table);
  EXPECT_TRUE(fs::is_symlink(link));
  EXPECT_EQ(read_text(target), "time_s\n2\n");
  int entries = 0;  // pipe, locked, target and link: no temporary or probe left behind
  for (const auto& entry : fs::directory_iterator(dir_)) {
    (void)entry;
    ++entries;
  }
  EXPECT_EQ(entries, 4);
}

TEST_F(CsvTest, WriteRejectsRowsOfTheWrongLengthAndKeysThatCannotRoundTrip) {
  CsvTable table;
  table.columns = {"time_s", "key_force_n"};
  table.rows = {{0.0}};
  EXPECT_THROW(write_csv(path("a.csv"), table), InputError);
  EXPECT_FALSE(fs::exists(path("a.csv")));
  table.rows = {{0.0, 1.0}};
  table.metadata["a:b"] = "c";
  EXPECT_THROW(format_csv(table), InputError);
}

TEST_F(CsvTest, ReadAcceptsSpacesBlankLinesCommentsCrLfAndByteOrderMark) {
  const std::string file = write_text("lenient.csv",
                                      "\xEF\xBB\xBF# action :  grand \r\n"
                                      "#just a remark\r\n"
                                      "\r\n"
                                      " time_s , \"key_force_n\"\r\n"
                                      "0, +1.5\r\n"
                                      "\r\n"
                                      "# a comment between rows\r\n"
                                      "  1e-3 ,-2\r\n");
  const CsvTable table = read_csv(file);
  EXPECT_EQ(table.metadata.at("action"), "grand");
  EXPECT_EQ(table.metadata.at("just a remark"), "");
  EXPECT_EQ(table.metadata.size(), 2u);
  EXPECT_EQ(table.columns, (std::vector<std::string>{"time_s", "key_force_n"}));
  ASSERT_EQ(table.rows.size(), 2u);
  EXPECT_EQ(table.rows[0], (std::vector<double>{0.0, 1.5}));
  EXPECT_EQ(table.rows[1], (std::vector<double>{0.001, -2.0}));
  EXPECT_EQ(table.column_index("key_force_n"), 1);
  EXPECT_EQ(table.column_index("hammer_angle_deg"), -1);
  EXPECT_EQ(table.column("key_force_n"), (std::vector<double>{1.5, -2.0}));
  EXPECT_THROW(table.column("hammer_angle_deg"), InputError);
}

TEST_F(CsvTest, WrongNumberOfValuesNamesFileAndLine) {
  const std::string message = read_error(
      "# action: grand\n# input: mass:1kg\ntime_s,key_angle_deg,key_force_n\n"
      "0,0,0\n0.001,0,0\n\n7e-3,1\n");
  EXPECT_TRUE(contains(message, "trace.csv: line 7: expected 3 values, got 2")) << message;
  const std::string extra = read_error("time_s,key_force_n\n0,1,\n");
  EXPECT_TRUE(contains(extra, "trace.csv: line 2: expected 2 values, got 3")) << extra;
}

TEST_F(CsvTest, TextInANumberColumnNamesFileLineAndColumn) {
  const std::string message = read_error("time_s,key_force_n\n0,1\n0.001,abc\n");
  EXPECT_TRUE(contains(message, "trace.csv: line 3: 'abc' in column key_force_n is not a number"))
      << message;
  const std::string comma = read_error("time_s,key_force_n\n0,1\n0,5,2\n");  // decimal comma
  EXPECT_TRUE(contains(comma, "line 3: expected 2 values, got 3")) << comma;
  const std::string partial = read_error("time_s,key_force_n\n0,1.5x\n");
  EXPECT_TRUE(contains(partial, "line 2: '1.5x' in column key_force_n is not a number")) << partial;
  const std::string empty = read_error("time_s,key_force_n\n0, \n");
  EXPECT_TRUE(contains(empty, "line 2: column key_force_n is empty")) << empty;
}

TEST_F(CsvTest, SemicolonsOrTabsBetweenColumnsAreNamedAsSuch) {
  // a spreadsheet's export in a decimal-comma locale: one header field "time_s;key_force_n",
  // which had been reported as a value in a column of that name that is not a number
  const std::string semicolons = read_error("time_s;key_force_n\n0;0\n0,01;5\n");
  EXPECT_TRUE(contains(semicolons, "trace.csv: line 1: the columns are separated by semicolons"))
      << semicolons;
  EXPECT_TRUE(contains(semicolons, "expected commas")) << semicolons;
  const std::string tabs = read_error("time_s\tkey_force_n\n0\t0\n");
  EXPECT_TRUE(contains(tabs, "separated by tabs")) << tabs;
}

TEST_F(CsvTest, NonFiniteValuesAreRejected) {
  for (const std::string value : {"nan", "inf", "-inf", "1e999"}) {
    const std::string message = read_error("time_s,key_force_n\n0,0\n1," + value + "\n");
    EXPECT_TRUE(contains(
        message, "trace.csv: line 3: '" + value + "' in column key_force_n is not a finite number"))
        << message;
  }
}

TEST_F(CsvTest, MissingFileAndMissingHeaderAreNamed) {
  const std::string missing = path("absent.csv");
  try {
    read_csv(missing);
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_TRUE(contains(e.what(), missing)) << e.what();
    EXPECT_TRUE(contains(e.what(), "does not exist")) << e.what();
  }
  const std::string only_metadata = read_error("# action: grand\n\n");
  EXPECT_TRUE(contains(only_metadata, "trace.csv: line 3: no header row")) << only_metadata;
  const std::string numbers = read_error("# action: grand\n0,1\n1,2\n");
  EXPECT_TRUE(contains(numbers, "trace.csv: line 2: expected a header row")) << numbers;
  const std::string twice = read_error("time_s,time_s\n");
  EXPECT_TRUE(contains(twice, "line 1: header column 'time_s' appears more than once")) << twice;
  const std::string unnamed = read_error("time_s,,key_force_n\n");
  EXPECT_TRUE(contains(unnamed, "line 1: header column 2 has no name")) << unnamed;
}

TEST_F(CsvTest, HeaderOnlyIsAnEmptyTable) {
  const CsvTable table = read_csv(write_text("empty.csv", "time_s,key_force_n\n"));
  EXPECT_EQ(table.columns.size(), 2u);
  EXPECT_TRUE(table.rows.empty());
}

}  // namespace
}  // namespace pat
