#include <deal.II/base/patterns.h>

#include <dealmpm/base/errors.h>
#include <dealmpm/base/parameter_file.h>
#include <dealmpm/core/simulation.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

using namespace dealmpm;

namespace
{
  /** What plain_pattern says for a pattern object and a value. */
  std::string
  words(const Patterns::PatternBase &pattern, const std::string &value = "")
  {
    return plain_pattern(pattern.description(), value);
  }
} // namespace

// The typed patterns that replaced Patterns::Anything keep the program's
// wording ("expected a number", "expected 2 positive integers").
TEST(PatternWords, NumbersInTheProgramsWords)
{
  EXPECT_EQ(words(Patterns::Double()), "a number");
  EXPECT_EQ(words(Patterns::Double(0)), "a number >= 0");
  EXPECT_EQ(words(Patterns::Double(0, 1)), "a number from 0 to 1");
  EXPECT_EQ(words(Patterns::Integer()), "an integer");
  EXPECT_EQ(words(Patterns::Integer(1)), "a positive integer");
  EXPECT_EQ(words(Patterns::Integer(2, 3)), "an integer from 2 to 3");
}

TEST(PatternWords, ListsSayTheCountOnlyWhenItIsWrong)
{
  const Patterns::List cells(Patterns::Integer(1), 2, 2);
  EXPECT_EQ(words(cells, "0, 20"), "positive integers");
  EXPECT_EQ(words(cells, "20"), "2 positive integers, comma-separated");
  const Patterns::List point(Patterns::Double(), 3, 3);
  EXPECT_EQ(words(point, "1, x, 2"), "numbers");
  EXPECT_EQ(words(point, "1, 2"), "3 numbers, comma-separated");
  EXPECT_EQ(words(Patterns::List(Patterns::Double(), 1), ""),
            "at least 1 numbers, comma-separated");
}

TEST(PatternWords, MultipleSelectionListsTheChoices)
{
  EXPECT_EQ(words(Patterns::MultipleSelection("gravity|local damping")),
            "a comma-separated list of: gravity, local damping");
}

// A Selection lists its choices and, for a value near one, suggests it.
TEST(PatternWords, SelectionListsItsChoicesAndTheNearest)
{
  EXPECT_EQ(words(Patterns::Selection("box|ball|cylinder"), "bal"),
            "one of 'box', 'ball', 'cylinder' (did you mean 'ball'?)");
  EXPECT_EQ(words(Patterns::Selection("box|ball|cylinder"), "BOX"),
            "one of 'box', 'ball', 'cylinder' (did you mean 'box'?)");
  // Two choices as near: both; none near: no guess.
  EXPECT_EQ(words(Patterns::Selection("USL|USF|MUSL"), "US"),
            "one of 'USL', 'USF', 'MUSL' (did you mean 'USL' or 'USF'?)");
  EXPECT_EQ(words(Patterns::Selection("USL|USF|MUSL"), "explicit"),
            "one of 'USL', 'USF', 'MUSL'");
}

// Other patterns are left to deal.II's text.
TEST(PatternWords, OthersHaveNoPlainForm)
{
  EXPECT_EQ(words(Patterns::Bool()), "");
  EXPECT_EQ(words(Patterns::List(Patterns::Selection("a|b"))), "");
  EXPECT_EQ(words(Patterns::FileName()), "");
}

// A value given with -s that its entry's typed pattern refuses: blamed on
// the command line, in the program's words.
TEST(PatternWords, OverrideRefusedInTheProgramsWords)
{
  ParameterHandler prm;
  prm.enter_subsection("Time");
  prm.declare_entry("End time", "1", Patterns::Double());
  prm.leave_subsection();
  try
    {
      apply_overrides(prm, {"Time/End time=soon"});
      FAIL() << "no error";
    }
  catch (const InputError &e)
    {
      EXPECT_EQ(std::string(e.what()),
                "command line: -s 'Time/End time=soon': expected a number");
    }
}

// The same in a scene file: the entry's section found from deal.II's line.
TEST(PatternWords, FileEntryRefusedInTheProgramsWords)
{
  // In the temporary folder: the tests may run from the source tree.
  const std::string file =
    (std::filesystem::temp_directory_path() / "pattern_words_test.prm")
      .string();
  std::ofstream(file)
    << "subsection Output\n  set Interval = 1 # comment\nend\n"
    << "subsection Time  # the times\n  subsection Inner\n  end\n"
    << "  set End time = soon\nend\n";
  ParameterHandler prm;
  for (const std::string section : {"Output", "Time"})
    {
      prm.enter_subsection(section);
      prm.declare_entry(section == "Time" ? "End time" : "Interval",
                        "1",
                        Patterns::Double());
      if (section == "Time")
        {
          prm.enter_subsection("Inner");
          prm.leave_subsection();
        }
      prm.leave_subsection();
    }
  try
    {
      parse_parameter_file(prm, file, false);
      FAIL() << "no error";
    }
  catch (const InputError &e)
    {
      EXPECT_EQ(std::string(e.what()),
                file + ": entry 'Time/End time' = 'soon': expected a number");
    }
  std::filesystem::remove(file);
}
