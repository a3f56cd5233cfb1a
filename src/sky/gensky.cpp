// gensky: CIE sky (and sun) descriptions for Radiance scenes. Output, warnings and errors
// follow Radiance 5.4a's gensky line for line; the formulas are in cie_sky.h and
// solar_position.h.
#include "radcl/sky/cie_sky.h"
#include "radcl/sky/program.h"
#include "radcl/sky/solar_position.h"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <cstring>

namespace radcl::sky {
namespace {

// Time zone names gensky accepts after the hour, with their standard meridians (degrees
// west). The order matters where a name repeats (AST/ADT/NDT): the first entry wins.
struct Zone {
  char name[8]; // zero-padded: gensky's comparison may look past the name's end
  double meridian;
};
const Zone kZones[] = {
    {"YST", 135},   {"YDT", 120},   {"PST", 120},  {"PDT", 105},  {"MST", 105},   {"MDT", 90},
    {"CST", 90},    {"CDT", 75},    {"EST", 75},   {"EDT", 60},   {"AST", 60},    {"ADT", 45},
    {"NST", 52.5},  {"NDT", 37.5},  {"GMT", 0},    {"BST", -15},  {"CET", -15},   {"CEST", -30},
    {"EET", -30},   {"EEST", -45},  {"AST", -45},  {"ADT", -60},  {"GST", -60},   {"GDT", -75},
    {"IST", -82.5}, {"IDT", -97.5}, {"JST", -135}, {"NDT", -150}, {"NZST", -180}, {"NZDT", -195},
};

class GenSky {
public:
  explicit GenSky(const std::vector<std::string>& argv) : argv_(argv) {}

  ProgramResult run() {
    try {
      main();
    } catch (const ProgramExit& e) {
      res_.status = e.status;
    }
    return std::move(res_);
  }

private:
  const std::vector<std::string>& argv_;
  ProgramResult res_;
  const char* prog() const { return argv_.empty() ? "gensky" : argv_[0].c_str(); }

  Site site_;
  int year_ = 0, month_ = 0, day_ = 0;
  double hour_ = 0;
  bool solar_time_ = false; // hour given as local solar time ("+" prefix)
  double altitude_ = 0, azimuth_ = 0;
  CieSky type_ = CieSky::clear;
  bool dosun_ = true;
  double zenith_ = 0;
  int zenith_units_ = 0; // 0 computed, 1 radiance given, -1 horizontal irradiance given
  double turbidity_ = 2.45;
  double ground_refl_ = 0.2;
  std::array<double, 3> sun_{};
  double ground_ = 0, f2_ = 0;
  double solar_ = 0;
  int solar_units_ = 0; // as zenith_units_

  [[noreturn]] void use_error(const std::string& msg) {
    appendf(res_.err, "%s: Use error - %s\n", prog(), msg.c_str());
    appendf(res_.err, "Usage: %s month day hour [options]\n", prog());
    appendf(res_.err, "   Or: %s -ang altitude azimuth [options]\n", prog());
    appendf(res_.err, "   Or: %s -defaults\n", prog());
    throw ProgramExit{1};
  }

  const char* value(std::size_t& i) {
    if (++i >= argv_.size()) use_error("arg count");
    return argv_[i].c_str();
  }

  void main() {
    const std::size_t argc = argv_.size();
    if (argc == 2 && argv_[1] == "-defaults") {
      print_defaults();
      return;
    }
    if (argc < 4) use_error("arg count");
    bool zone_given = false;
    if (argv_[1] == "-ang") {
      altitude_ = std::atof(argv_[2].c_str()) * kDeg;
      azimuth_ = std::atof(argv_[3].c_str()) * kDeg;
      month_ = 0;
    } else {
      month_ = std::atoi(argv_[1].c_str());
      if (month_ < 1 || month_ > 12) use_error("bad month");
      day_ = std::atoi(argv_[2].c_str());
      if (day_ < 1 || day_ > 31) use_error("bad day");
      zone_given = parse_hour(argv_[3].c_str());
    }
    for (std::size_t i = 4; i < argc; ++i) {
      const char* a = argv_[i].c_str();
      if (a[0] != '-' && a[0] != '+') use_error("bad option");
      switch (a[1]) {
      case 's':
        type_ = CieSky::clear;
        dosun_ = a[0] == '+';
        break;
      case 'y':
        year_ = std::atoi(value(i));
        break;
      case 'r':
      case 'R':
        solar_units_ = a[1] == 'R' ? -1 : 1;
        solar_ = std::atof(value(i));
        break;
      case 'c':
        type_ = CieSky::overcast;
        break;
      case 'u':
        type_ = CieSky::uniform;
        break;
      case 'i':
        type_ = CieSky::intermediate;
        dosun_ = a[0] == '+';
        break;
      case 't':
        turbidity_ = std::atof(value(i));
        break;
      case 'b':
      case 'B':
        zenith_units_ = a[1] == 'B' ? -1 : 1;
        zenith_ = std::atof(value(i));
        break;
      case 'g':
        ground_refl_ = std::atof(value(i));
        break;
      case 'a':
        site_.latitude = std::atof(value(i)) * kDeg;
        break;
      case 'o':
        site_.longitude = std::atof(value(i)) * kDeg;
        break;
      case 'm':
        if (zone_given) { // a time zone on the hour overrides -m
          value(i);
          break;
        }
        site_.meridian = std::atof(value(i)) * kDeg;
        break;
      default:
        use_error(std::string("unknown option: ") + a);
      }
    }
    if (year_ && ((year_ < 1950) | (year_ > 2050)))
      appendf(res_.err, "%s: warning - year should be in range 1950-2050\n", prog());
    if (month_ && !solar_time_ && std::fabs(site_.meridian - site_.longitude) > 45 * kPi / 180)
      appendf(res_.err, "%s: warning - %.1f hours btwn. standard meridian and longitude\n", prog(),
              (site_.longitude - site_.meridian) * 12 / kPi);
    res_.out += "# " + format_command_line(argv_);
    compute();
    print();
  }

  // The hour: "H", "H.h" or "H:MM", "+" in front for solar time, optionally followed by a
  // time zone name (standard time only). Returns whether a zone set the meridian.
  bool parse_hour(const char* hs) {
    const char* cp = hs;
    solar_time_ = *cp == '+';
    if (solar_time_) ++cp;
    while (std::isdigit(static_cast<unsigned char>(*cp)))
      ++cp;
    if (*cp == ':') {
      ++cp;
      hour_ = std::atoi(hs) + std::atoi(cp) / 60.0;
    } else {
      hour_ = std::atof(hs);
      if (*cp == '.') ++cp;
    }
    while (std::isdigit(static_cast<unsigned char>(*cp)))
      ++cp;
    if (!*cp) return false;
    if (solar_time_ || !std::isalpha(static_cast<unsigned char>(*cp))) {
      appendf(res_.err, "%s: bad time format: %s\n", prog(), hs);
      throw ProgramExit{1};
    }
    for (const Zone& z : kZones) {
      std::size_t j = 0;
      // gensky upper-cases by clearing bit 5, so only ASCII letters compare sensibly
      while (j < 7 && cp[j] && (cp[j] & ~0x20) == z.name[j])
        ++j;
      if (!cp[j] && !z.name[j]) {
        site_.meridian = z.meridian * kDeg;
        return true;
      }
    }
    appendf(res_.err, "%s: unknown time zone: %s\n", prog(), cp);
    res_.err += "Known time zones:\n\t";
    for (std::size_t i = 0; i < std::size(kZones); ++i)
      appendf(res_.err, i ? " %s" : "%s", kZones[i].name);
    res_.err += '\n';
    throw ProgramExit{1};
  }

  void compute() {
    if (month_) {
      double decl, st = hour_;
      if (year_) {
        const double n = almanac_day(year_, month_, day_, hour_, site_);
        decl = almanac_declination(n, site_, solar_time_ ? nullptr : &st);
      } else {
        const int jd = day_of_year(month_, day_);
        decl = declination(jd);
        if (!solar_time_) st = hour_ + solar_time_offset(jd, site_);
      }
      altitude_ = solar_altitude(decl, st, site_);
      azimuth_ = solar_azimuth(decl, st, site_);
      appendf(res_.out, "# Local solar time: %.2f\n", st);
      appendf(res_.out, "# Solar altitude and azimuth: %.1f %.1f\n", 180. / kPi * altitude_,
              180. / kPi * azimuth_);
    }
    const bool overcast = is_overcast(type_);
    if (!overcast && altitude_ > 87. * kPi / 180.) {
      appendf(res_.err, "%s: warning - sun too close to zenith, reducing altitude to 87 degrees\n",
              prog());
      res_.out += "# warning - sun too close to zenith, reducing altitude to 87 degrees\n";
      altitude_ = 87. * kPi / 180.;
    }
    sun_ = sun_direction(altitude_, azimuth_);
    if (!overcast) f2_ = cie_f2(type_, altitude_);
    const double norm = cie_normfactor(type_, altitude_);
    if (zenith_units_ == -1)
      zenith_ /= norm * kPi;
    else if (zenith_units_ == 0)
      zenith_ = cie_zenith_radiance(type_, altitude_, turbidity_);
    ground_ = zenith_ * norm;
    appendf(res_.out, "# Ground ambient level: %.1f\n", ground_);
    if (!overcast && sun_[2] > 0.0 && (!solar_units_ || solar_ > 0.0)) {
      if (solar_units_ == -1)
        solar_ /= 6e-5 * sun_[2]; // horizontal direct irradiance over the sun's solid angle
      else if (solar_units_ == 0) {
        solar_ = 1.5e9 / 208. * (1.147 - .147 / (sun_[2] > .16 ? sun_[2] : .16));
        if (type_ == CieSky::intermediate) solar_ *= 0.15; // gensky's hazy-sun factor
      }
      ground_ += 6e-5 / kPi * solar_ * sun_[2];
    } else {
      dosun_ = false;
    }
    ground_ *= ground_refl_;
  }

  void print() {
    std::string& o = res_.out;
    if (dosun_) {
      o += "\nvoid light solar\n0\n0\n";
      appendf(o, "3 %.2e %.2e %.2e\n", solar_, solar_, solar_);
      o += "\nsolar source sun\n0\n0\n";
      appendf(o, "4 %f %f %f 0.5\n", sun_[0], sun_[1], sun_[2]);
    }
    o += "\nvoid brightfunc skyfunc\n2 skybr skybright.cal\n0\n";
    if (is_overcast(type_))
      appendf(o, "3 %d %.2e %.2e\n", static_cast<int>(type_), zenith_, ground_);
    else
      appendf(o, "7 %d %.2e %.2e %.2e %f %f %f\n", static_cast<int>(type_), zenith_, ground_, f2_,
              sun_[0], sun_[1], sun_[2]);
  }

  void print_defaults() {
    std::string& o = res_.out;
    o += dosun_ ? "+s\t\t\t\t# Sunny sky with sun\n" : "-s\t\t\t\t# Sunny sky without sun\n";
    appendf(o, "-g %f\t\t\t# Ground plane reflectance\n", ground_refl_);
    appendf(o, "-t %f\t\t\t# Atmospheric turbidity\n", turbidity_);
    appendf(o, "-a %f\t\t\t# Site latitude (degrees)\n", site_.latitude * (180 / kPi));
    appendf(o, "-o %f\t\t\t# Site longitude (degrees)\n", site_.longitude * (180 / kPi));
    appendf(o, "-m %f\t\t\t# Standard meridian (degrees)\n", site_.meridian * (180 / kPi));
  }
};

} // namespace

ProgramResult run_gensky(const std::vector<std::string>& argv) {
  return GenSky(argv).run();
}

} // namespace radcl::sky
