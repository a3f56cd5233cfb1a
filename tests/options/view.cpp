// View lines, view options and setview()'s checks.
#include "radcl/options/view.h"

#include <cmath>
#include <gtest/gtest.h>
#include <sstream>

using namespace radcl::options;

TEST(View, ScanLineSkipsOtherWords) {
  View v;
  EXPECT_EQ(scan_view_line(v, "rpict -vf x.vf -x 384 -vp 1 2 3 -ab 2 -vtl -vd 0 0 -1 -vh\n"), 3);
  EXPECT_EQ(v.point, (Vec3{1, 2, 3}));
  EXPECT_EQ(v.type, 'l');
  EXPECT_EQ(v.direction, (Vec3{0, 0, -1}));
  EXPECT_DOUBLE_EQ(v.horiz, 45); // "-vh" without a value is skipped
  View w;
  EXPECT_EQ(scan_view_line(w, "VIEW= -vth -vp 0 -7 2.2 -vu 0 1 0 -vh 180 -vv 180 -vs .5"), 6);
  EXPECT_EQ(w.type, 'h');
  EXPECT_DOUBLE_EQ(w.shift, .5);
  EXPECT_EQ(scan_view_line(w, "   "), 0);
}

TEST(View, IsViewLine) {
  EXPECT_TRUE(is_view_line("VIEW= -vtv", "rpict"));
  EXPECT_TRUE(is_view_line("rview -vtv", "rpict"));
  EXPECT_TRUE(is_view_line("/usr/local/bin/rvu -vtv", "rpict"));
  EXPECT_TRUE(is_view_line("rpiece -vtv", "rpict"));
  EXPECT_TRUE(is_view_line("pinterp -vtv", "rpict"));
  EXPECT_TRUE(is_view_line("rpictx -vtv", "rpict")); // a prefix match, as Radiance's
  EXPECT_TRUE(is_view_line("radcl_rpict -vp 1 2 3", "/opt/bin/radcl_rpict"));
  EXPECT_FALSE(is_view_line("oconv x.rad", "rpict"));
  EXPECT_FALSE(is_view_line("rtrace -vp 1 2 3", "rpict"));
  EXPECT_TRUE(is_view_line("rtrace -vp 1 2 3", "rtrace"));
}

TEST(View, ReadHeaderStopsAtEmptyLine) {
  std::istringstream in("#?RADIANCE\nrview -vtl -vh 3\nVIEW= -vv 4\n\nVIEW= -vh 99\n");
  View v;
  EXPECT_EQ(read_view_header(in, v, "rpict"), 2);
  EXPECT_EQ(v.type, 'l');
  EXPECT_DOUBLE_EQ(v.horiz, 3);
  EXPECT_DOUBLE_EQ(v.vert, 4);
  std::istringstream binary(std::string("\x01\x02rview -vtl\n", 12));
  EXPECT_EQ(read_view_header(binary, v, "rpict"), 0);
}

TEST(View, FormatView) {
  View v;
  EXPECT_EQ(format_view(v),
            " -vtv -vp 0 0 0 -vd 0 1 0 -vu 0 0 1 -vh 45 -vv 45 -vo 0 -va 0 -vs 0 -vl 0");
  v.direction = {0, 1, -0.25};
  v.point = {1.23456789, 0, 1e-7};
  ASSERT_EQ(setup_view(v), "");
  EXPECT_EQ(format_view(v), " -vtv -vp 1.23457 0 1e-07 -vd 0 1 -0.25 -vu 0 0 1 -vh 45 -vv 45 "
                            "-vo 0 -va 0 -vs 0 -vl 0");
}

TEST(View, SetupChecks) {
  auto err = [](auto change) {
    View v;
    change(v);
    return setup_view(v);
  };
  EXPECT_EQ(err([](View&) {}), "");
  EXPECT_EQ(err([](View& v) { v.fore = -1; }), "illegal fore/aft clipping plane");
  EXPECT_EQ(err([](View& v) { v.fore = 2, v.aft = 1; }), "illegal fore/aft clipping plane");
  EXPECT_EQ(err([](View& v) { v.direction = {0, 0, 0}; }), "zero view direction");
  EXPECT_EQ(err([](View& v) { v.up = {0, 0, 0}; }), "zero view up vector");
  EXPECT_EQ(err([](View& v) { v.up = {0, 2, 0}; }), "view up parallel to view direction");
  EXPECT_EQ(err([](View& v) { v.horiz = 0; }), "illegal horizontal view size");
  EXPECT_EQ(err([](View& v) { v.vert = -1; }), "illegal vertical view size");
  EXPECT_EQ(err([](View& v) { v.horiz = 179.9; }), "");
  EXPECT_EQ(err([](View& v) { v.horiz = 180; }), "illegal horizontal view size");
  EXPECT_EQ(err([](View& v) { v.type = 'c', v.horiz = 360; }), "");
  EXPECT_EQ(err([](View& v) { v.type = 'c', v.vert = 180; }), "illegal vertical view size");
  EXPECT_EQ(err([](View& v) { v.type = 'h', v.horiz = 180, v.vert = 180; }), "");
  EXPECT_EQ(err([](View& v) { v.type = 'h', v.horiz = 181; }), "illegal horizontal view size");
  EXPECT_EQ(err([](View& v) { v.type = 'a', v.horiz = 360, v.vert = 360; }), "");
  EXPECT_EQ(err([](View& v) { v.type = 's', v.horiz = 360; }), "illegal horizontal view size");
  EXPECT_EQ(err([](View& v) { v.type = 'l', v.horiz = 1000; }), "");
  EXPECT_EQ(err([](View& v) { v.type = 'q'; }), "unknown view type");
}

TEST(View, SetupDerivedVectors) {
  View v; // perspective 45x45 looking along +y, up +z
  ASSERT_EQ(setup_view(v), "");
  const double hn = 2 * std::tan(45.0 * M_PI / 360);
  EXPECT_NEAR(v.hvec[0], hn, 1e-12); // D x U = +x
  EXPECT_NEAR(v.vvec[2], hn, 1e-12);
  EXPECT_NEAR(v.hn2, hn * hn, 1e-12);
  View a;
  a.type = 'a';
  a.horiz = a.vert = 180;
  ASSERT_EQ(setup_view(a), "");
  EXPECT_NEAR(a.hvec[0], 1, 1e-12); // fisheye vectors stay unit
  EXPECT_NEAR(a.hn2, M_PI * M_PI, 1e-12);
}
