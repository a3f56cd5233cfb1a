// The chart is an SVG document an XML parser reads, with one circle per run, the Pareto front
// as a line through its points in order of time, the target and the recommended run marked.
#include <gtest/gtest.h>
#include <pugixml.hpp>

#include <cstdio>

#include "radcl/cost/svg_chart.h"

using namespace radcl::cost;

namespace {

Chart sample() {
  Chart c;
  c.title = "office <clear> & sky"; // needs escaping
  c.y_label = "p95 relative error";
  c.target = 0.02;
  c.series.push_back({"radcl",
                      "#1f77b4",
                      {{0.7, 0.08, "-aa 0.25", true},
                       {1.7, 0.018, "-aa 0.15", true},
                       {2.5, 0.03, "-aa 0 -ad 1024", false}}});
  c.series.push_back({"Radiance", "#ff7f0e", {{8.7, 0.02, "-aa 0.15", true}}});
  c.recommended_series = 0;
  c.recommended_point = 1;
  return c;
}

} // namespace

TEST(SvgChart, ParsesWithOnePointPerRun) {
  const std::string svg = render_svg(sample());
  pugi::xml_document doc;
  ASSERT_TRUE(doc.load_string(svg.c_str())) << svg;
  const pugi::xml_node root = doc.child("svg");
  ASSERT_TRUE(root);
  EXPECT_EQ(root.select_nodes("//circle[@class='run']").size(), 4u);
  EXPECT_EQ(root.select_nodes("//g[@data-name='radcl']/circle[@class='run']").size(), 3u);
  EXPECT_EQ(root.select_nodes("//circle[@class='recommended']").size(), 1u);
  EXPECT_EQ(root.select_nodes("//line[@class='target']").size(), 1u);
  EXPECT_NE(std::string(root.child("text").text().as_string()).find("<clear> & sky"),
            std::string::npos);
  // radcl's front joins its two front points, in order of time; Radiance's single point has
  // no line.
  const auto lines = root.select_nodes("//polyline[@class='pareto']");
  ASSERT_EQ(lines.size(), 1u);
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  ASSERT_EQ(std::sscanf(lines[0].node().attribute("points").value(), "%lf,%lf %lf,%lf", &x0, &y0,
                        &x1, &y1),
            4);
  EXPECT_LT(x0, x1); // later is to the right
  EXPECT_LT(y0, y1); // less error is lower on the page: a larger y
}

TEST(SvgChart, LogAxesPlacePointsByDecade) {
  Chart c;
  c.series.push_back(
      {"radcl", "blue", {{1, 0.01, "a", true}, {10, 0.1, "b", true}, {100, 1, "c", true}}});
  pugi::xml_document doc;
  ASSERT_TRUE(doc.load_string(render_svg(c).c_str()));
  std::vector<double> cx, cy;
  for (const auto& n : doc.select_nodes("//circle[@class='run']")) {
    cx.push_back(n.node().attribute("cx").as_double());
    cy.push_back(n.node().attribute("cy").as_double());
  }
  ASSERT_EQ(cx.size(), 3u);
  EXPECT_NEAR(cx[1] - cx[0], cx[2] - cx[1], 0.2); // equal steps per decade
  EXPECT_NEAR(cy[0] - cy[1], cy[1] - cy[2], 0.2);
}
