#include "edgefit/report/table.h"

#include <gtest/gtest.h>

namespace edgefit {
namespace {

Table Example() {
  Table table;
  table.heading = "Table 2: translation error per joint [mm]";
  table.caption = "conveyor (mm):";
  table.header = {"posture", "lifter_1_joint"};
  table.rows = {{"load", "0.0169"}, {"<unload>", "(0.0041)"}};
  table.note = "In brackets: joints the fit called unobservable.";
  return table;
}

TEST(TableTest, MarkdownHasHeadingCaptionRuleRowsAndNote) {
  EXPECT_EQ(MarkdownTable(Example()),
            "\n## Table 2: translation error per joint [mm]\n"
            "\nconveyor (mm):\n"
            "\n| posture | lifter_1_joint |\n|---|---|\n| load | 0.0169 |\n"
            "| <unload> | (0.0041) |\n"
            "\nIn brackets: joints the fit called unobservable.\n");
}

TEST(TableTest, HtmlEscapesEveryCell) {
  const std::string html = HtmlTable(Example());
  EXPECT_NE(html.find("<h2>Table 2: translation error per joint [mm]</h2>"), std::string::npos);
  EXPECT_NE(html.find("<th>posture</th><th>lifter_1_joint</th>"), std::string::npos);
  EXPECT_NE(html.find("<td>&lt;unload&gt;</td>"), std::string::npos) << html;
  EXPECT_EQ(html.find("<unload>"), std::string::npos);
}

TEST(TableTest, AHeadingAloneHasNoTable) {
  Table table;
  table.heading = "Table 1: rotation error per joint [deg]";
  table.note = "No revolute joints in these assets.";
  EXPECT_EQ(HtmlTable(table).find("<table>"), std::string::npos);
  EXPECT_EQ(MarkdownTable(table),
            "\n## Table 1: rotation error per joint [deg]\n\nNo revolute joints in these assets.\n");
}

}  // namespace
}  // namespace edgefit
