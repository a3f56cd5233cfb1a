// Reading BSDF XML files: the reference files genBSDF made, and the messages for bad files.
#include "radcl/bsdf/xml_reader.h"
#include "radcl/util/error.h"

#include "test_env.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

using namespace radcl::bsdf;

namespace {

std::vector<std::string> g_warnings;
void keep_warning(const std::string& msg) {
  g_warnings.push_back(msg);
}

// A small valid Klems file (the 9-patch basis of klems_3ring.xml, all values 0.1), with its
// pieces open to change.
struct KlemsText {
  std::string structure = "Columns";
  std::string basis_def = "<AngleBasis><AngleBasisName>Ring</AngleBasisName>"
                          "<AngleBasisBlock><nPhis>1</nPhis><ThetaBounds><LowerTheta>0"
                          "</LowerTheta><UpperTheta>30</UpperTheta></ThetaBounds>"
                          "</AngleBasisBlock>"
                          "<AngleBasisBlock><nPhis>8</nPhis><ThetaBounds><LowerTheta>30"
                          "</LowerTheta><UpperTheta>90</UpperTheta></ThetaBounds>"
                          "</AngleBasisBlock></AngleBasis>";
  std::string column = "Ring", row = "Ring";
  std::string direction = "Transmission Front";
  std::string values = std::string(81 * 4, ' ');
  std::string wavelength = "Visible";
  bool with_data = true;

  KlemsText() {
    values.clear();
    for (int k = 0; k < 81; ++k)
      values += k % 9 == 8 ? "0.1\n" : "0.1 ";
  }

  std::string str() const {
    std::string s = "<?xml version=\"1.0\"?>\n<WindowElement>\n<FileType>BSDF</FileType>\n"
                    "<Optical>\n<Layer>\n<DataDefinition>\n<IncidentDataStructure>" +
                    structure + "</IncidentDataStructure>\n" + basis_def + "\n</DataDefinition>\n";
    if (with_data)
      s += "<WavelengthData>\n<Wavelength unit=\"Integral\">" + wavelength +
           "</Wavelength>\n<WavelengthDataBlock>\n<WavelengthDataDirection>" + direction +
           "</WavelengthDataDirection>\n<ColumnAngleBasis>" + column +
           "</ColumnAngleBasis>\n<RowAngleBasis>" + row + "</RowAngleBasis>\n<ScatteringData>\n" +
           values + "</ScatteringData>\n</WavelengthDataBlock>\n</WavelengthData>\n";
    return s + "</Layer>\n</Optical>\n</WindowElement>\n";
  }
};

// A small valid TT3 file with the given ScatteringData.
std::string tt3_text(const std::string& tree, const std::string& basis = "LBNL/Shirley-Chiu") {
  return "<WindowElement><Optical><Layer><DataDefinition><IncidentDataStructure>TensorTree3"
         "</IncidentDataStructure></DataDefinition>\n<WavelengthData><Wavelength>Visible"
         "</Wavelength><WavelengthDataBlock><WavelengthDataDirection>Reflection Back"
         "</WavelengthDataDirection><AngleBasis>" +
         basis + "</AngleBasis>\n<ScatteringData>\n" + tree +
         "\n</ScatteringData></WavelengthDataBlock></WavelengthData></Layer></Optical>"
         "</WindowElement>";
}

// The message of the FatalError that parsing `text` throws ("" when none).
std::string error_of(const std::string& text) {
  try {
    parse_bsdf_xml(text, "bad.xml");
  } catch (const radcl::FatalError& e) {
    return e.what();
  }
  return "";
}

} // namespace

TEST(BsdfXml, BlindsKlems) {
  const BsdfData d = read_bsdf_xml(radcl::test::data("scenes/blinds_klems.xml"));
  EXPECT_EQ(d.name, radcl::test::data("scenes/blinds_klems.xml"));
  EXPECT_EQ(d.format, Format::Klems);
  EXPECT_EQ(d.material, "Name");
  EXPECT_EQ(d.manufacturer, "Manufacturer");
  EXPECT_EQ(d.device_type, "Other");
  EXPECT_DOUBLE_EQ(d.thickness, 0.0375911);
  EXPECT_DOUBLE_EQ(d.width, 0.55);
  EXPECT_DOUBLE_EQ(d.height, 1.1836908);
  EXPECT_EQ(d.mgf.rfind("xf -t -0.000000 -0.578165 0\n# bsdf_blinds.mgf", 0), 0u);
  EXPECT_EQ(d.mgf_scale, 1);
  // genBSDF wrote the room-side components (WINDOW's back): front transmission and reflection.
  ASSERT_EQ(d.components.size(), 2u);
  const Component& t = d.components[0];
  const Component& r = d.components[1];
  EXPECT_EQ(t.part, Part::TransmitFront);
  EXPECT_EQ(t.direction, "Transmission Back");
  EXPECT_EQ(r.part, Part::ReflectFront);
  EXPECT_EQ(r.direction, "Reflection Back");
  EXPECT_EQ(t.scattering_type, "BTDF");
  EXPECT_EQ(r.scattering_type, "BTDF"); // as genBSDF writes it; not used
  EXPECT_EQ(d.find(Part::TransmitBack), nullptr);
  for (const Component* c : {&t, &r}) {
    EXPECT_EQ(c->format, Format::Klems);
    EXPECT_FALSE(c->colour());
    EXPECT_EQ(c->klems.in_basis.name(), "LBNL/Klems Full");
    EXPECT_EQ(c->klems.in_basis.size(), 145);
    EXPECT_EQ(c->klems.out_basis.size(), 145);
    EXPECT_EQ(c->klems.y.size(), 145u * 145u);
  }
  // The first and last numbers of the transmission, and the start of its second row (the
  // second outgoing patch: the file's incident directions are its columns).
  EXPECT_EQ(t.klems.value(0, 0), 2.468e+01f);
  EXPECT_EQ(t.klems.value(144, 144), 3.732e+00f);
  EXPECT_EQ(t.klems.value(0, 1), 8.371e-04f);
  EXPECT_EQ(t.klems.value(1, 0), 6.446e-04f);
}

TEST(BsdfXml, FilmAndGlossyTensorTrees) {
  const BsdfData film = read_bsdf_xml(radcl::test::data("scenes/film_t3.xml"));
  EXPECT_EQ(film.format, Format::TensorTree3);
  EXPECT_DOUBLE_EQ(film.thickness, 0.004);
  EXPECT_TRUE(film.mgf.empty());
  ASSERT_EQ(film.components.size(), 4u);
  const Part parts[] = {Part::TransmitFront, Part::ReflectFront, Part::TransmitBack,
                        Part::ReflectBack};
  for (int k = 0; k < 4; ++k) {
    const Component& c = film.components[k];
    EXPECT_EQ(c.part, parts[k]);
    EXPECT_EQ(c.format, Format::TensorTree3);
    EXPECT_EQ(c.tree.y.ndim, 3);
    EXPECT_EQ(c.tree.y.nodes[0], -1);
    EXPECT_FALSE(c.colour());
  }
  // The first leaves of the front transmission: the file's first four-level path.
  const TensorTree& y = film.components[0].tree.y;
  int32_t k = 0;
  for (int level = 0; level < 4; ++level)
    k = y.nodes[k + 1];
  EXPECT_EQ(y.nodes[k], 0);
  EXPECT_EQ(y.values[y.nodes[k + 1]], 8.697516e-02f);
  EXPECT_EQ(y.values[y.nodes[k + 1] + 1], 8.579259e-02f);
  EXPECT_EQ(y.values[y.nodes[k + 1] + 2], 0.0890325f); // the first value of a 2x2x2 grid

  const BsdfData glossy = read_bsdf_xml(radcl::test::data("scenes/glossy_t3.xml"));
  EXPECT_EQ(glossy.format, Format::TensorTree3);
  ASSERT_EQ(glossy.components.size(), 2u);
  EXPECT_EQ(glossy.components[0].part, Part::TransmitFront);
  EXPECT_EQ(glossy.components[1].part, Part::ReflectFront);
  // An opaque tile, but genBSDF's transmission has 18 leaves of light near grazing incidence
  // (evaluate.cpp), the largest 2.2545903.
  int lit = 0;
  float largest = 0;
  for (float v : glossy.components[0].tree.y.values) {
    lit += v != 0;
    largest = std::max(largest, v);
  }
  EXPECT_EQ(lit, 18);
  EXPECT_EQ(largest, 2.2545903f);
}

TEST(BsdfXml, MaterialUnits) {
  const BsdfData d = read_bsdf_xml(radcl::test::data("bsdf/klems_3ring.xml"));
  EXPECT_EQ(d.material, "Ring test");
  EXPECT_DOUBLE_EQ(d.thickness, 0.006);
  EXPECT_DOUBLE_EQ(d.width, 0.254);
  EXPECT_DOUBLE_EQ(d.height, 1.5);
}

TEST(BsdfXml, MissingFileIsASystemError) {
  const std::string path = radcl::test::data("bsdf/no_such_file.xml");
  try {
    read_bsdf_xml(path);
    FAIL() << "no error";
  } catch (const radcl::SystemError& e) {
    EXPECT_NE(std::string(e.what()).find("\"" + path + "\""), std::string::npos) << e.what();
  }
  EXPECT_THROW(read_bsdf_xml(radcl::test::data("bsdf")), radcl::SystemError); // a folder
}

TEST(BsdfXml, ValidTemplatesRead) {
  EXPECT_EQ(error_of(KlemsText().str()), "");
  EXPECT_EQ(error_of(tt3_text("{ 1 }")), "");
  const BsdfData d = parse_bsdf_xml(KlemsText().str(), "ok.xml");
  EXPECT_EQ(d.components.at(0).part, Part::TransmitBack);
  EXPECT_EQ(d.components[0].klems.in_basis.size(), 9);
}

TEST(BsdfXml, BadXml) {
  EXPECT_EQ(error_of("<WindowElement>\n<Optical>\n</WindowElement>\n"),
            "\"bad.xml\" line 3: XML error: Start-end tags mismatch");
  EXPECT_EQ(error_of(""), "\"bad.xml\" line 1: XML error: No document element found");
  EXPECT_EQ(error_of("<Window/>"),
            "\"bad.xml\": top-level element is <Window>, not <WindowElement>");
  EXPECT_EQ(error_of("<WindowElement><FileType>IGDB</FileType></WindowElement>"),
            "\"bad.xml\": wrong FileType \"IGDB\" (must be \"BSDF\")");
  EXPECT_EQ(error_of("<WindowElement><Optical/></WindowElement>"),
            "\"bad.xml\": no optical layer (<Optical><Layer>)");
}

TEST(BsdfXml, MissingOrUnusableData) {
  KlemsText k;
  k.with_data = false;
  EXPECT_EQ(error_of(k.str()), "\"bad.xml\": no <WavelengthData>");
  k = KlemsText();
  k.wavelength = "CIE-X";
  g_warnings.clear();
  radcl::set_warning_sink(keep_warning);
  EXPECT_EQ(error_of(k.str()), "\"bad.xml\": no \"Visible\" scattering data");
  k.wavelength = "Solar"; // skipped silently, as Radiance does
  EXPECT_EQ(error_of(k.str()), "\"bad.xml\": no \"Visible\" scattering data");
  k = KlemsText();
  k.direction = "Transmission Sideways";
  EXPECT_EQ(error_of(k.str()), "\"bad.xml\": no \"Visible\" scattering data");
  radcl::set_warning_sink(nullptr);
  ASSERT_EQ(g_warnings.size(), 2u);
  EXPECT_EQ(g_warnings[0],
            "\"bad.xml\": ignoring \"Transmission Front\": it has no \"Visible\" data");
  EXPECT_EQ(g_warnings[1],
            "\"bad.xml\": ignoring data with WavelengthDataDirection \"Transmission Sideways\"");
  EXPECT_EQ(error_of("<WindowElement><Optical><Layer/></Optical></WindowElement>"),
            "\"bad.xml\": missing <IncidentDataStructure>");
}

TEST(BsdfXml, AngleBases) {
  KlemsText k;
  k.column = "X";
  EXPECT_EQ(error_of(k.str()), "\"bad.xml\" line 14: unknown angle basis \"X\"");
  k = KlemsText();
  k.row = "";
  EXPECT_EQ(error_of(k.str()),
            "\"bad.xml\" line 12: missing <RowAngleBasis> for \"Transmission Front\"");
  // A built-in basis needs no definition; its name is matched without regard to case.
  k = KlemsText();
  k.column = k.row = "lbnl/klems quarter";
  k.basis_def.clear();
  EXPECT_EQ(error_of(k.str()),
            "\"bad.xml\" line 16: <ScatteringData> for \"Transmission Front\" has 81 values, not "
            "41 x 41 = 1681");
  // A definition under a built-in name keeps the built-in basis, as in Radiance.
  k = KlemsText();
  k.basis_def.replace(k.basis_def.find(">Ring<"), 6, ">LBNL/Klems Full<");
  k.column = k.row = "LBNL/Klems Full";
  EXPECT_NE(error_of(k.str()).find("not 145 x 145 = 21025"), std::string::npos);
  // Bad definitions.
  k = KlemsText();
  k.basis_def.replace(k.basis_def.find("<LowerTheta>30"), 14, "<LowerTheta>25");
  EXPECT_EQ(error_of(k.str()), "\"bad.xml\" line 8: theta bounds disagree in angle basis \"Ring\"");
  k = KlemsText();
  k.basis_def.replace(k.basis_def.find("<nPhis>8"), 8, "<nPhis>1");
  EXPECT_EQ(error_of(k.str()),
            "\"bad.xml\" line 8: angle basis \"Ring\": illegal phi count 1 at theta 30");
  k = KlemsText();
  k.basis_def.replace(k.basis_def.find("<nPhis>8"), 8, "<nPhis>8x");
  EXPECT_EQ(error_of(k.str()), "\"bad.xml\" line 8: bad integer \"8x\" in <nPhis>");
  k = KlemsText();
  k.basis_def.replace(k.basis_def.find(">90<"), 4, ">20<");
  EXPECT_EQ(error_of(k.str()),
            "\"bad.xml\" line 8: angle basis \"Ring\": bad theta bounds 30 to 20");
}

TEST(BsdfXml, MatrixValues) {
  KlemsText k;
  k.values += " 0.1";
  EXPECT_EQ(error_of(k.str()),
            "\"bad.xml\" line 16: <ScatteringData> for \"Transmission Front\" has 82 values, not "
            "9 x 9 = 81");
  k = KlemsText();
  k.values.resize(k.values.size() - 4);
  EXPECT_NE(error_of(k.str()).find("has 80 values, not 9 x 9 = 81"), std::string::npos);
  k = KlemsText();
  k.values.replace(4 * 20, 3, "0.x"); // on the third line of values
  EXPECT_EQ(
      error_of(k.str()),
      "\"bad.xml\" line 19: bad number \"0.x\" in <ScatteringData> for \"Transmission Front\"");
  k = KlemsText();
  k.values.replace(4 * 30, 3, "abc");
  EXPECT_EQ(error_of(k.str()),
            "\"bad.xml\" line 20: bad number \"abc\" in <ScatteringData> for \"Transmission "
            "Front\"");
  k = KlemsText();
  k.values = "";
  EXPECT_EQ(error_of(k.str()),
            "\"bad.xml\" line 16: missing <ScatteringData> for \"Transmission Front\"");
  // Commas may separate values, and negative values read as 0.
  k = KlemsText();
  k.values.replace(0, 4, "-3, ");
  const BsdfData d = parse_bsdf_xml(k.str(), "ok.xml");
  EXPECT_EQ(d.components[0].klems.y[0], 0.0f);
  EXPECT_EQ(d.components[0].klems.y[1], 0.1f);
  k.structure = "Diagonal";
  EXPECT_EQ(error_of(k.str()),
            "\"bad.xml\" line 7: unsupported IncidentDataStructure \"Diagonal\"");
}

TEST(BsdfXml, MalformedTensorTrees) {
  EXPECT_EQ(error_of(tt3_text("{ 1 2 3 }")),
            "\"bad.xml\" line 4: tensor tree leaf of 3 values (must be 1 or a power of 8) for "
            "\"Reflection Back\"");
  EXPECT_EQ(error_of(tt3_text("{ {1} {2} {3} {4} {5} {6} {7} {8}\n")),
            "\"bad.xml\" line 6: missing '}' in tensor tree for \"Reflection Back\"");
  EXPECT_EQ(error_of(tt3_text("{\n{1} {2} {3} {4} {5} {6} {7} {z}\n}")),
            "\"bad.xml\" line 5: bad number \"z\" in tensor tree for \"Reflection Back\"");
  EXPECT_EQ(error_of(tt3_text("{ 1 } 2")),
            "\"bad.xml\" line 4: extra characters after the tensor tree for \"Reflection Back\"");
  EXPECT_EQ(error_of(tt3_text("1")),
            "\"bad.xml\" line 4: missing '{' in tensor tree for \"Reflection Back\"");
  EXPECT_EQ(error_of(tt3_text("")),
            "\"bad.xml\" line 3: missing <ScatteringData> for \"Reflection Back\"");
  EXPECT_EQ(error_of(tt3_text("{ 1 }", "LBNL/Klems Full")),
            "\"bad.xml\" line 2: unknown angle basis \"LBNL/Klems Full\" for a tensor tree");
}

namespace {

// `text` with `xml` inserted just after <Layer>.
std::string in_layer(std::string text, const std::string& xml) {
  const size_t at = text.find("<Layer>") + 7;
  return text.insert(at, xml);
}

// `text` with its <WavelengthData> element repeated for another wavelength and direction.
std::string with_copy(std::string text, const std::string& wavelength,
                      const std::string& direction) {
  const size_t b = text.find("<WavelengthData>");
  const size_t e = text.find("</WavelengthData>") + 17;
  std::string copy = text.substr(b, e - b);
  copy.replace(copy.find(">Visible<") + 1, 7, wavelength);
  const size_t d = copy.find("<WavelengthDataDirection>") + 25;
  copy.replace(d, copy.find('<', d) - d, direction);
  return text.insert(e, "\n" + copy);
}

} // namespace

TEST(BsdfXml, MaterialAndGeometry) {
  const std::string ok = tt3_text("{ 1 }");
  const BsdfData d = parse_bsdf_xml(
      in_layer(ok, "<Material><Width unit=\"foot\">2</Width></Material><Geometry format=\"MGF\">"
                   "<MGFblock unit=\"Centimeter\">\n  v v1 =\n</MGFblock></Geometry>"),
      "ok.xml");
  EXPECT_DOUBLE_EQ(d.width, 0.6096);
  EXPECT_EQ(d.thickness, 0);
  EXPECT_EQ(d.mgf, "v v1 =\n");
  EXPECT_EQ(d.mgf_scale, 0.01);
  EXPECT_EQ(error_of(in_layer(ok, "<Material><Width unit=\"cubit\">2</Width></Material>")),
            "\"bad.xml\" line 1: unknown unit \"cubit\" in <Width>");
  EXPECT_EQ(error_of(in_layer(ok, "<Material><Thickness>-1</Thickness></Material>")),
            "\"bad.xml\" line 1: negative <Thickness>");
  EXPECT_EQ(error_of(in_layer(ok, "<Material><Height>1.2m</Height></Material>")),
            "\"bad.xml\" line 1: bad number \"1.2m\" in <Height>");
  EXPECT_EQ(error_of(in_layer(ok, "<Geometry format=\"OBJ\"/>")),
            "\"bad.xml\" line 1: unsupported geometry format \"OBJ\"");
  std::string deep;
  for (int k = 0; k < 40; ++k)
    deep += "{ ";
  EXPECT_EQ(error_of(tt3_text(deep)),
            "\"bad.xml\" line 4: tensor tree nested too deeply for \"Reflection Back\"");
}

TEST(BsdfXml, ColourAndRepeatedData) {
  g_warnings.clear();
  radcl::set_warning_sink(keep_warning);
  const std::string base = KlemsText().str();
  // CIE-X without CIE-Z: grey, with a warning.
  BsdfData d = parse_bsdf_xml(with_copy(base, "CIE-X", "Transmission Front"), "c.xml");
  EXPECT_FALSE(d.components.at(0).colour());
  // Both: colour. A second Visible block for the same direction replaces the first.
  d = parse_bsdf_xml(
      with_copy(with_copy(base, "CIE-X", "Transmission Front"), "CIE-Z", "Transmission Front"),
      "c.xml");
  EXPECT_TRUE(d.components.at(0).colour());
  EXPECT_EQ(d.components[0].klems.x.size(), 81u);
  d = parse_bsdf_xml(with_copy(base, "Visible", "Transmission Front"), "c.xml");
  EXPECT_EQ(d.components.size(), 1u);
  // Another direction makes another component, in the file's order.
  d = parse_bsdf_xml(with_copy(base, "Visible", "Reflection Front"), "c.xml");
  ASSERT_EQ(d.components.size(), 2u);
  EXPECT_EQ(d.components[1].part, Part::ReflectBack);
  radcl::set_warning_sink(nullptr);
  ASSERT_EQ(g_warnings.size(), 2u);
  EXPECT_EQ(g_warnings[0], "\"c.xml\": \"Transmission Front\" is grey: its CIE-X and CIE-Z data "
                           "are incomplete or of another size");
  EXPECT_EQ(g_warnings[1],
            "\"c.xml\": second \"Visible\" data for \"Transmission Front\" replaces the first");
  // Tensor trees take u' and v' for colour; CIE-X is skipped there.
  const std::string tt = tt3_text("{ 1 }");
  d = parse_bsdf_xml(
      with_copy(with_copy(tt, "CIE-u", "Reflection Back"), "CIE-v", "Reflection Back"), "t.xml");
  EXPECT_TRUE(d.components.at(0).colour());
  d = parse_bsdf_xml(
      with_copy(with_copy(tt, "CIE-X", "Reflection Back"), "CIE-Z", "Reflection Back"), "t.xml");
  EXPECT_FALSE(d.components.at(0).colour());
}
