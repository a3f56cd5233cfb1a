// gendaylit: Perez all-weather sky (and sun) descriptions from measured or modelled
// irradiances/illuminances. Output, warnings and the "error sky" it prints when the model
// cannot apply follow Radiance 5.4a's gendaylit; the formulas are in perez.h.
#include "radcl/sky/cie_sky.h"
#include "radcl/sky/perez.h"
#include "radcl/sky/program.h"
#include "radcl/sky/solar_position.h"

#include <cmath>
#include <cstdlib>

namespace radcl::sky {
namespace {

const double kSolarConstant = 1367;      // W/m^2
const double kSolarConstantLux = 127500; // lux
const double kHalfSunAngle = 0.2665;     // degrees
const double kWhiteEfficacy = 179;       // lm/W, Radiance's conversion
// The model's validity range for clearness and brightness: inputs are clamped into it.
const double kClearnessMin = 1.0, kClearnessMax = 12.01;
const double kBrightnessMin = 0.01, kBrightnessMax = 0.6;

double deg2rad(double d) {
  return d * (kPi / 180.);
}

class GenDaylit {
public:
  explicit GenDaylit(const std::vector<std::string>& argv) : argv_(argv) {}

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
  const char* prog() const { return argv_.empty() ? "gendaylit" : argv_[0].c_str(); }

  Site site_;
  int year_ = 0, month_ = 0, day_ = 0;
  double hour_ = 0;
  bool solar_time_ = false;
  double altitude_ = 0, azimuth_ = 0;
  double st_ = 0;
  double day_number_ = 0; // stays 0 with -ang (gendaylit then uses day 0's eccentricity)

  double epsilon_ = 0, delta_ = 0; // Perez sky clearness and brightness
  double diffuse_lux_ = 0, direct_lux_ = 0;
  double diffuse_irr_ = 0, direct_irr_ = 0, global_irr_ = 0;
  double sun_zenith_deg_ = 0;
  double water_ = 0;               // atmospheric precipitable water (cm)
  double dew_point_ = 10.97353115; // the default gives exactly 2 cm of water
  int output_ = 0;                 // 0 visible W, 1 solar W, 2 lumen
  int input_ = 0;                  // 0 -P, 1 -W, 2 -L, 3 -G, 4 -E
  bool color_ = false;
  bool quiet_ = false;
  int cloudy_ = 0;
  bool dosun_ = true;
  double turbidity_ = 0.1; // accepted, unused (as in gendaylit)
  double ground_refl_ = 0.2;
  float interval_ = 0; // minutes between data points (-i)
  std::array<double, 3> sun_{};
  PerezCoefficients k_;
  double diffnorm_ = 0, solar_ = 0, ground_ = 0;
  // Chromaticity locus of the colour model (-C), gendaylit's defaults (Berlin).
  float locus_[11] = {-4.843e9f,  2.5568e6f, 0.24282e3f, 0.23258f, -4.843e9f, 2.5568e6f,
                      0.24282e3f, 0.23258f,  -1.2848f,   1.7519f,  -0.093786f};

  [[noreturn]] void use_error(const std::string& msg) {
    std::string& e = res_.err;
    appendf(e, "%s: Use error - %s\n\n", prog(), msg.c_str());
    appendf(e, "Usage: %s      month day hour [-y year]\t[...]\n", prog());
    appendf(e, "   or: %s -ang altitude azimuth\t\t[...]\n", prog());
    e += "\t\tfollowed by:\t  -P          epsilon delta [options]\n";
    e += "\t\t\t or:\t  [-W|-L|-G]  direct_value diffuse_value [options]\n";
    e += "\t\t\t or:\t  -E          global_irradiance [options]\n\n";
    e += "    Description:\n";
    e += "\t-P epsilon delta  (these are the Perez parameters) \n";
    e += "\t-W direct-normal-irradiance diffuse-horizontal-irradiance (W/m^2)\n";
    e += "\t-L direct-normal-illuminance diffuse-horizontal-illuminance (lux)\n";
    e += "\t-G direct-horizontal-irradiance diffuse-horizontal-irradiance (W/m^2)\n";
    e += "\t-E global-horizontal-irradiance (W/m^2)\n\n";
    e += "\tOutput specification with option:\n";
    e += "\t-O [0|1|2]  (0=output in W/m^2/sr visible, 1=output in W/m^2/sr solar, 2=output in "
         "candela/m^2), default is 0 \n";
    e += "\tgendaylit version 2.5 (2018/04/18)  \n\n";
    throw ProgramExit{1};
  }

  void warn(const char* msg) {
    if (!quiet_) res_.err += msg;
  }

  double value(std::size_t& i) {
    if (++i >= argv_.size()) use_error("arg count");
    return std::atof(argv_[i].c_str());
  }

  // The option at argv_[i] and its values (i moves past them).
  void option(std::size_t& i) {
    const std::string& a = argv_[i];
    if (a[0] != '-' && a[0] != '+') use_error("bad option");
    switch (a.size() > 1 ? a[1] : '\0') {
    case 'd':
      dew_point_ = value(i);
      if (dew_point_ < -40 || dew_point_ > 40) dew_point_ = 10.97353115;
      break;
    case 's':
      cloudy_ = 0;
      dosun_ = a[0] == '+';
      break;
    case 'y':
      value(i);
      year_ = std::atoi(argv_[i].c_str());
      break;
    case 'R': // solar radiance: accepted and ignored, as in gendaylit
      value(i);
      break;
    case 'c':
      cloudy_ = a[0] == '+' ? 2 : 1;
      dosun_ = false;
      break;
    case 'C':
      if (a.compare(1, 3, "CIE") == 0) {
        const float cie[11] = {-4.607e9f,  2.9678e6f, 0.09911e3f, 0.244063f, -2.0064e9f, 1.9018e6f,
                               0.24748e3f, 0.23704f,  -3.0f,      2.87f,     -0.275f};
        std::copy(cie, cie + 11, locus_);
      } else {
        color_ = true;
      }
      break;
    case 'l':
      for (int j = 0; j < 4; ++j)
        locus_[j] = locus_[j + 4] = static_cast<float>(value(i));
      for (int j = 8; j < 11; ++j)
        locus_[j] = static_cast<float>(value(i));
      break;
    case 't':
      turbidity_ = value(i);
      break;
    case 'w':
      quiet_ = true;
      break;
    case 'b': // zenith brightness: accepted, only -defaults would show it
      value(i);
      break;
    case 'g':
      ground_refl_ = value(i);
      break;
    case 'a':
      site_.latitude = value(i) * (kPi / 180);
      break;
    case 'o':
      site_.longitude = value(i) * (kPi / 180);
      break;
    case 'm':
      site_.meridian = value(i) * (kPi / 180);
      break;
    case 'O':
      output_ = static_cast<int>(value(i));
      break;
    case 'P':
      input_ = 0;
      epsilon_ = value(i);
      delta_ = value(i);
      break;
    case 'W': // direct normal and diffuse horizontal irradiance
      input_ = 1;
      direct_irr_ = value(i);
      diffuse_irr_ = value(i);
      break;
    case 'L': // direct normal and diffuse horizontal illuminance
      input_ = 2;
      direct_lux_ = value(i);
      diffuse_lux_ = value(i);
      break;
    case 'G': // direct horizontal and diffuse horizontal irradiance
      input_ = 3;
      direct_irr_ = value(i);
      diffuse_irr_ = value(i);
      break;
    case 'E': // global horizontal irradiance, split by the Erbs model
      input_ = 4;
      global_irr_ = value(i);
      break;
    case 'i':
      interval_ = static_cast<float>(value(i));
      break;
    default:
      use_error("unknown option: " + a);
    }
  }

  void main() {
    const std::size_t argc = argv_.size();
    if (argc == 2 && argv_[1] == "-defaults") {
      print_defaults();
      return;
    }
    if (argc < 4) use_error("arg count");
    if (argv_[1] == "-ang") {
      altitude_ = std::atof(argv_[2].c_str()) * (kPi / 180);
      azimuth_ = std::atof(argv_[3].c_str()) * (kPi / 180);
      month_ = 0;
    } else {
      month_ = std::atoi(argv_[1].c_str());
      if (month_ < 1 || month_ > 12) use_error("bad month");
      day_ = std::atoi(argv_[2].c_str());
      if (day_ < 1 || day_ > 31) use_error("bad day");
      hour_ = std::atof(argv_[3].c_str());
      if (hour_ < 0 || hour_ >= 24) use_error("bad hour");
      solar_time_ = argv_[3][0] == '+';
    }
    for (std::size_t i = 4; i < argc; ++i)
      option(i);
    if (month_ && !solar_time_ && std::fabs(site_.meridian - site_.longitude) > 45 * kPi / 180)
      appendf(res_.err, "%s: warning: %.1f hours btwn. standard meridian and longitude\n", prog(),
              (site_.longitude - site_.meridian) * 12 / kPi);
    water_ = std::exp(0.07 * dew_point_ - 0.075);
    res_.out += '#';
    for (const std::string& w : argv_)
      res_.out += ' ' + w;
    res_.out += '\n';
    compute();
    print();
  }

  // --- the error sky: printed whenever the model cannot be applied; the program then ends.
  [[noreturn]] void error_sky() {
    sun_ = sun_direction(altitude_, azimuth_);
    appendf(res_.out, "# Local solar time: %.2f\n", st_);
    appendf(res_.out, "# Solar altitude and azimuth: %.1f %.1f\n", altitude_ * 180 / kPi,
            azimuth_ * 180 / kPi);
    res_.out += "\nvoid brightfunc skyfunc\n2 skybright perezlum.cal\n0\n";
    appendf(res_.out, "10 0.00 0.00  0.000 0.000 0.000 0.000 0.000  %f %f %f \n", sun_[0], sun_[1],
            sun_[2]);
    throw ProgramExit{0};
  }

  // Sunrise and sunset (solar time, hours) of the IES model; gendaylit works in single
  // precision here.
  double sun_half_day(float& w) const {
    w = static_cast<float>(
        -1 * (std::tan(site_.latitude) * std::tan(declination(day_of_year(month_, day_)))));
    return (kPi / 2 -
            std::atan2(static_cast<double>(w), std::sqrt(static_cast<double>(1 - w * w)))) *
           180 / (kPi * 15);
  }
  double sunrise() const {
    float w;
    return 12 - sun_half_day(w);
  }
  double sunset() const {
    float w;
    return 12 + sun_half_day(w);
  }

  void compute_sun_position() {
    double decl;
    st_ = hour_;
    if (year_) {
      const double n = almanac_day(year_, month_, day_, hour_, site_);
      decl = almanac_declination(n, site_, solar_time_ ? nullptr : &st_);
    } else {
      const int jd = day_of_year(month_, day_);
      decl = declination(jd);
      if (!solar_time_) st_ = hour_ + solar_time_offset(jd, site_);
    }
    if (interval_) {
      if (interval_ < 0) {
        res_.err += "time interval negative\n";
        throw ProgramExit{1};
      }
      // Near sunrise and sunset the sun is placed mid-way through the part of the interval
      // it is up.
      if (std::fabs(sunrise() - st_) <= interval_ / 120) {
        st_ = (st_ + interval_ / 120 + sunrise()) / 2;
        if (!quiet_)
          appendf(res_.err, "Solar position corrected at time step %d %d %.3f\n", month_, day_,
                  hour_);
      }
      if (std::fabs(sunset() - st_) < interval_ / 120) {
        st_ = (st_ - interval_ / 120 + sunset()) / 2;
        if (!quiet_)
          appendf(res_.err, "Solar position corrected at time step %d %d %.3f\n", month_, day_,
                  hour_);
      }
      if (st_ < sunrise() - interval_ / 120 || st_ > sunset() + interval_ / 120) {
        if (!quiet_)
          appendf(res_.err, "Warning: sun position too low, printing error sky at %d %d %.3f\n",
                  month_, day_, hour_);
        altitude_ = solar_altitude(decl, st_, site_);
        azimuth_ = solar_azimuth(decl, st_, site_);
        error_sky();
      }
    } else if (st_ < sunrise() || st_ > sunset()) {
      if (!quiet_)
        appendf(res_.err,
                "Warning: sun altitude below zero at time step %i %i %.2f, printing error sky\n",
                month_, day_, hour_);
      altitude_ = solar_altitude(decl, st_, site_);
      azimuth_ = solar_azimuth(decl, st_, site_);
      error_sky();
    }
    altitude_ = solar_altitude(decl, st_, site_);
    azimuth_ = solar_azimuth(decl, st_, site_);
    day_number_ = day_of_year(month_, day_);
  }

  // --- Perez parameters and the quantities they come from
  void clamp_parameters() {
    if (epsilon_ < kClearnessMin) epsilon_ = kClearnessMin;
    if (epsilon_ > kClearnessMax) epsilon_ = kClearnessMax - 0.001;
    if (delta_ < kBrightnessMin) delta_ = kBrightnessMin;
    if (delta_ > kBrightnessMax) delta_ = kBrightnessMax;
  }

  double eccentricity() const { // (R0/R)^2
    const double a = 2 * kPi * (day_number_ - 1) / 365;
    return 1.00011 + 0.034221 * std::cos(a) + 0.00128 * std::sin(a) + 0.000719 * std::cos(2 * a) +
           0.000077 * std::sin(2 * a);
  }

  double air_mass() {
    if (sun_zenith_deg_ > 90) {
      warn("Warning: air mass has reached the maximal value\n");
      sun_zenith_deg_ = 90;
    }
    return 1 / (std::cos(sun_zenith_deg_ * kPi / 180) +
                0.15 * std::exp(std::log(93.885 - sun_zenith_deg_) * (-1.253)));
  }

  // 1.041 Z^3 of the clearness formula, Z the sun zenith angle in radians.
  double z3_term() const {
    const double z = sun_zenith_deg_;
    return 1.041 * z * kPi / 180 * z * kPi / 180 * z * kPi / 180;
  }

  double brightness_from_irradiance() {
    return diffuse_irr_ * air_mass() / (kSolarConstant * eccentricity());
  }
  double clearness_from_irradiance() const {
    return ((diffuse_irr_ + direct_irr_) / (diffuse_irr_) + z3_term()) / (1 + z3_term());
  }
  double diffuse_from_brightness() {
    return delta_ / air_mass() * (kSolarConstant * eccentricity());
  }
  double direct_from_clearness() {
    return diffuse_from_brightness() * ((epsilon_ - 1) * (1 + z3_term()));
  }

  double diffuse_efficacy() {
    clamp_parameters();
    const double e = perez_diffuse_efficacy(epsilon_, delta_, water_, sun_zenith_deg_);
    if (e < 0) { // epsilon in no bin (not a number)
      if (!quiet_)
        appendf(res_.err, "Warning: sky clearness (= %.3f) too high, printing error sky\n",
                epsilon_);
      error_sky();
    }
    return e;
  }
  double direct_efficacy() const {
    return perez_direct_efficacy(epsilon_, delta_, water_, sun_zenith_deg_);
  }

  void check_illuminances() {
    if (direct_lux_ < 0) {
      warn("Warning: direct illuminance < 0. Using 0.0\n");
      direct_lux_ = 0.0;
    }
    if (diffuse_lux_ < 0) {
      warn("Warning: diffuse illuminance < 0. Using 0.0\n");
      diffuse_lux_ = 0.0;
    }
    if (direct_lux_ + diffuse_lux_ == 0 && altitude_ > 0) {
      warn("Warning: zero illuminance at sun altitude > 0, printing error sky\n");
      error_sky();
    }
    if (direct_lux_ > kSolarConstantLux) {
      warn("Warning: direct illuminance exceeds solar constant\n");
      error_sky();
    }
  }

  void check_irradiances() {
    if (direct_irr_ < 0) {
      warn("Warning: direct irradiance < 0. Using 0.0\n");
      direct_irr_ = 0.0;
    }
    if (diffuse_irr_ < 0) {
      warn("Warning: diffuse irradiance < 0. Using 0.0\n");
      diffuse_irr_ = 0.0;
    }
    if (direct_irr_ + diffuse_irr_ == 0 && altitude_ > 0) {
      warn("Warning: zero irradiance at sun altitude > 0, printing error sky\n");
      error_sky();
    }
    if (direct_irr_ > kSolarConstant) {
      warn("Warning: direct irradiance exceeds solar constant\n");
      error_sky();
    }
  }

  // Illuminances from irradiances through the Perez efficacy models (-O 0 and 2 need them).
  void illuminances_from_irradiances() {
    if (output_ != 0 && output_ != 2) return;
    diffuse_lux_ = diffuse_irr_ * diffuse_efficacy();
    direct_lux_ = direct_irr_ * direct_efficacy();
    check_illuminances();
  }

  void parameters_from_irradiances() {
    check_irradiances();
    delta_ = brightness_from_irradiance();
    epsilon_ = clearness_from_irradiance();
    clamp_parameters();
    illuminances_from_irradiances();
  }

  // -L: irradiances (and so epsilon and delta) from illuminances, by fixed-point iteration
  // on the efficacy models. gendaylit's loop condition always holds once the parameters are
  // clamped, so it runs its full nine rounds.
  void irradiances_from_illuminances() {
    diffuse_irr_ = diffuse_lux_ * kSolarConstant / (kSolarConstantLux);
    direct_irr_ = direct_lux_ * kSolarConstant / (kSolarConstantLux);
    epsilon_ = clearness_from_irradiance();
    delta_ = brightness_from_irradiance();
    clamp_parameters();
    for (int round = 0; round < 9; ++round) {
      diffuse_irr_ = diffuse_lux_ / diffuse_efficacy();
      const double d_eff = direct_efficacy();
      direct_irr_ = d_eff < 0.1 ? 0 : direct_lux_ / d_eff;
      delta_ = brightness_from_irradiance();
      epsilon_ = clearness_from_irradiance();
      clamp_parameters();
    }
  }

  void compute() {
    if (month_) compute_sun_position();
    if (!cloudy_ && altitude_ > 87. * kPi / 180.) {
      if (!quiet_)
        appendf(res_.err,
                "%s: warning - sun too close to zenith, reducing altitude to 87 degrees\n", prog());
      altitude_ = 87. * kPi / 180.;
    }
    sun_ = sun_direction(altitude_, azimuth_);
    sun_zenith_deg_ = 90 - altitude_ * 180 / kPi;

    switch (input_) {
    case 0: // -P
      clamp_parameters();
      diffuse_irr_ = diffuse_from_brightness();
      direct_irr_ = direct_from_clearness();
      check_irradiances();
      illuminances_from_irradiances();
      break;
    case 1: // -W
      parameters_from_irradiances();
      break;
    case 2: // -L
      check_illuminances();
      irradiances_from_illuminances();
      clamp_parameters();
      break;
    case 3: // -G: direct horizontal to direct normal
      if (altitude_ <= 0) {
        warn("Warning: sun altitude < 0, proceed with irradiance values of zero\n");
        direct_irr_ = 0;
        diffuse_irr_ = 0;
      } else {
        direct_irr_ = direct_irr_ / std::sin(altitude_);
      }
      parameters_from_irradiances();
      break;
    case 4: // -E
      erbs_split();
      parameters_from_irradiances();
      break;
    }

    const double z = deg2rad(sun_zenith_deg_);
    if (epsilon_ < kClearnessMin || epsilon_ >= kClearnessMax) {
      res_.err += "Error: epsilon out of range in function coeff_lum_perez!\n";
      throw ProgramExit{1};
    }
    k_ = perez_coefficients(z, epsilon_, delta_);
    const double integral = perez_discrete_integral(k_, z);
    if (output_ == 0)
      diffnorm_ = diffuse_lux_ / integral / kWhiteEfficacy;
    else if (output_ == 1)
      diffnorm_ = diffuse_irr_ / integral;
    else if (output_ == 2)
      diffnorm_ = diffuse_lux_ / integral;
    else {
      res_.err += "Wrong output specification.\n";
      throw ProgramExit{1};
    }
    // Solar radiance: direct normal quantity over the sun disc's solid angle.
    const double disc = 2 * kPi * (1 - std::cos(kHalfSunAngle * kPi / 180));
    if (output_ == 0)
      solar_ = direct_lux_ / disc / kWhiteEfficacy;
    else if (output_ == 1)
      solar_ = direct_irr_ / disc;
    else
      solar_ = direct_lux_ / disc;

    // Ground radiance from gensky's CIE normalisation for the nearest CIE sky type.
    const double zenith = perez_relative_luminance(k_, 0.0, z) * diffnorm_;
    double norm = 0;
    if (epsilon_ == 1) norm = 0.777778;
    if (epsilon_ >= 6) norm = cie_normfactor(CieSky::clear, altitude_);
    if (epsilon_ > 1 && epsilon_ < 6) norm = cie_normfactor(CieSky::intermediate, altitude_);
    ground_ = zenith * norm;
    if (dosun_ && epsilon_ > 1) ground_ += 6.8e-5 / kPi * solar_ * sun_[2];
    ground_ *= ground_refl_;

    if (k_.b > 0) {
      if (!quiet_)
        appendf(res_.err, "Warning: positive Perez parameter B (= %lf), printing error sky\n",
                k_.b);
      error_sky();
    }
  }

  // Erbs et al. (1982): diffuse fraction of the global horizontal irradiance from the
  // clearness index kt.
  void erbs_split() {
    if (altitude_ <= 0) {
      if (!quiet_ && global_irr_ > 50)
        res_.err += "Warning: global irradiance higher than 50 W/m^2 while the sun altitude is "
                    "lower than zero\n";
      global_irr_ = diffuse_irr_ = direct_irr_ = 0;
      return;
    }
    const double s0 = kSolarConstant * eccentricity() * std::sin(altitude_);
    if (global_irr_ > s0) {
      warn("Warning: global irradiance is higher than the time-dependent solar constant s0\n");
      global_irr_ = s0 * 0.999;
    }
    const double kt = global_irr_ / s0;
    if (kt <= 0.22)
      diffuse_irr_ = global_irr_ * (1 - 0.09 * kt);
    else if (kt <= 0.8)
      diffuse_irr_ = global_irr_ * (0.9511 - 0.1604 * kt + 4.388 * std::pow(kt, 2) -
                                    16.638 * std::pow(kt, 3) + 12.336 * std::pow(kt, 4));
    else if (kt < 1)
      diffuse_irr_ = global_irr_ * (0.165);
    direct_irr_ = global_irr_ - diffuse_irr_;
    appendf(res_.out, "# erbs_s0, erbs_kt, irr_dir_h, irr_diff: %.3f %.3f %.3f %.3f\n", s0, kt,
            direct_irr_, diffuse_irr_);
    res_.out += "# WARNING: the -E option is only recommended for a rough estimation!\n";
    direct_irr_ = direct_irr_ / std::sin(altitude_);
  }

  void print() {
    std::string& o = res_.out;
    appendf(o, "# Local solar time: %.2f\n", st_);
    appendf(o, "# Solar altitude and azimuth: %.1f %.1f\n", altitude_ * 180 / kPi,
            azimuth_ * 180 / kPi);
    appendf(o, "# epsilon, delta, atmospheric precipitable water content : %.4f %.4f %.4f \n",
            epsilon_, delta_, water_);
    if (dosun_) {
      o += "\nvoid light solar\n0\n0\n";
      if (epsilon_ > 1)
        appendf(o, "3 %.3e %.3e %.3e\n", solar_, solar_, solar_);
      else
        o += "3 0.0 0.0 0.0\n";
      o += "\nsolar source sun\n0\n0\n";
      appendf(o, "4 %f %f %f %f\n", sun_[0], sun_[1], sun_[2], 2 * kHalfSunAngle);
    }
    if (color_ && epsilon_ < 4.5 && epsilon_ > 1.065) {
      appendf(res_.err, "\twarning: sky clearness(epsilon)= %f \n", epsilon_);
      res_.err += "\twarning: intermediate sky!! \n";
      res_.err += "\twarning: color model for intermediate sky pending  \n";
      res_.err += "\twarning: no color output ! \n";
      color_ = false;
    }
    if (color_) {
      o += "\nvoid colorfunc skyfunc\n4 skybright_r skybright_g skybright_b perezlum_c.cal\n0\n";
      appendf(o, "22 %.3e %.3e %lf %lf %lf %lf %lf %f %f %f %f", diffnorm_, ground_, k_.a, k_.b,
              k_.c, k_.d, k_.e, sun_[0], sun_[1], sun_[2], epsilon_);
      for (float l : locus_)
        appendf(o, " %f", static_cast<double>(l));
      o += '\n';
    } else {
      o += "\nvoid brightfunc skyfunc\n2 skybright perezlum.cal\n0\n";
      appendf(o, "10 %.3e %.3e %lf %lf %lf %lf %lf %f %f %f \n", diffnorm_, ground_, k_.a, k_.b,
              k_.c, k_.d, k_.e, sun_[0], sun_[1], sun_[2]);
    }
  }

  void print_defaults() {
    appendf(res_.out, "-g %f\t\t\t# Ground plane reflectance\n", ground_refl_);
    appendf(res_.out, "-t %f\t\t\t# Atmospheric betaturbidity\n", turbidity_);
    appendf(res_.out, "-a %f\t\t\t# Site latitude (degrees)\n", site_.latitude * (180 / kPi));
    appendf(res_.out, "-o %f\t\t\t# Site longitude (degrees)\n", site_.longitude * (180 / kPi));
    appendf(res_.out, "-m %f\t\t\t# Standard meridian (degrees)\n", site_.meridian * (180 / kPi));
  }
};

} // namespace

ProgramResult run_gendaylit(const std::vector<std::string>& argv) {
  return GenDaylit(argv).run();
}

} // namespace radcl::sky
