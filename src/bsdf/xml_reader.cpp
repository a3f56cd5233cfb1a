#include "radcl/bsdf/xml_reader.h"

#include "radcl/util/error.h"
#include "scan.h"

#include <pugixml.hpp>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <optional>
#include <strings.h>
#include <utility>

namespace radcl::bsdf {

namespace {

bool same(const std::string& a, const char* b) {
  return strcasecmp(a.c_str(), b) == 0;
}

// Text of an element's character data, with its offset in the document.
struct Text {
  std::string value;
  size_t offset = 0;
};

Text text_of(pugi::xml_node node) {
  Text t;
  bool first = true;
  for (pugi::xml_node c = node.first_child(); c; c = c.next_sibling()) {
    if (c.type() != pugi::node_pcdata && c.type() != pugi::node_cdata) continue;
    if (first)
      t.offset = static_cast<size_t>(std::max<ptrdiff_t>(c.offset_debug(), 0));
    else
      t.value += ' '; // pieces split by a comment
    t.value += c.value();
    first = false;
  }
  return t;
}

std::string trimmed(pugi::xml_node node) {
  const std::string s = text_of(node).value;
  const size_t b = detail::skip_space(s, 0);
  size_t e = s.size();
  while (e > b && detail::is_space(s[e - 1]))
    --e;
  return s.substr(b, e - b);
}

std::string quoted(const std::string& s) {
  return "\"" + s + "\"";
}

enum Channel { kY, kX, kZ, kU, kV, kChannels };
const char* const kChannelNames[kChannels] = {"Visible", "CIE-X", "CIE-Z", "CIE-u", "CIE-v"};

struct PartName {
  const char* file_name;
  Part part;
};
// The file's names are WINDOW's, whose front is Radiance's back (bsdf_data.h).
const PartName kParts[] = {
    {"Transmission Front", Part::TransmitBack},
    {"Transmission Back", Part::TransmitFront},
    {"Reflection Front", Part::ReflectBack},
    {"Reflection Back", Part::ReflectFront},
};

// One component as it is read: its channels may come from several <WavelengthData>.
struct Pending {
  Component comp;
  KlemsMatrix mtx[3]; // Y, X, Z
  TensorTree tree[3]; // Y, u', v'
  bool have[kChannels] = {};
};

class Reader {
public:
  Reader(const std::string& text, const std::string& name) : text_(text), name_(name) {}

  BsdfData read() {
    pugi::xml_document doc;
    const pugi::xml_parse_result res = doc.load_buffer(
        text_.data(), text_.size(), pugi::parse_default & ~pugi::parse_eol, pugi::encoding_auto);
    if (!res)
      fail_at(static_cast<size_t>(res.offset), std::string("XML error: ") + res.description());
    const pugi::xml_node root = doc.document_element();
    if (std::strcmp(root.name(), "WindowElement") != 0)
      fail(std::string("top-level element is <") + root.name() + ">, not <WindowElement>");
    if (pugi::xml_node ft = root.child("FileType"); ft && trimmed(ft) != "BSDF")
      fail("wrong FileType " + quoted(trimmed(ft)) + " (must be \"BSDF\")");
    const pugi::xml_node layer = root.child("Optical").child("Layer");
    if (!layer) fail("no optical layer (<Optical><Layer>)");

    data_.name = name_;
    read_material(layer);
    read_geometry(layer);
    read_format(layer);
    if (data_.format == Format::Klems) read_bases(layer.child("DataDefinition"));
    read_wavelength_data(layer);
    finish();
    return std::move(data_);
  }

private:
  [[noreturn]] void fail(const std::string& msg) const {
    throw FatalError(quoted(name_) + ": " + msg);
  }
  [[noreturn]] void fail_at(size_t offset, const std::string& msg) const {
    const size_t end = std::min(offset, text_.size());
    const auto line = 1 + std::count(text_.begin(), text_.begin() + end, '\n');
    throw FatalError(quoted(name_) + " line " + std::to_string(line) + ": " + msg);
  }
  [[noreturn]] void fail_at(pugi::xml_node node, const std::string& msg) const {
    fail_at(static_cast<size_t>(std::max<ptrdiff_t>(node.offset_debug(), 0)), msg);
  }
  void warn(const std::string& msg) const { warning(quoted(name_) + ": " + msg); }

  double real(pugi::xml_node node) const {
    const std::string s = trimmed(node);
    double v = 0;
    if (s.empty() || detail::scan_real(s, 0, &v) != s.size())
      fail_at(node, "bad number " + quoted(s) + " in <" + node.name() + ">");
    return v;
  }

  int integer(pugi::xml_node node) const {
    const std::string s = trimmed(node);
    size_t i = !s.empty() && (s[0] == '+' || s[0] == '-') ? 1 : 0;
    const size_t start = i;
    while (i < s.size() && detail::is_digit(s[i]))
      ++i;
    if (i == start || i != s.size() || i - start > 9)
      fail_at(node, "bad integer " + quoted(s) + " in <" + node.name() + ">");
    return std::stoi(s);
  }

  // Meters per unit of a length's "unit" attribute (meters when absent), as Radiance knows them.
  double meters(pugi::xml_node node) const {
    const pugi::xml_attribute a = node.attribute("unit");
    if (!a) return 1;
    const std::string u = a.value();
    const std::pair<const char*, double> units[] = {{"Meter", 1},
                                                    {"Foot", 0.3048},
                                                    {"Inch", 0.0254},
                                                    {"Centimeter", 0.01},
                                                    {"Millimeter", 0.001}};
    for (const auto& [n, f] : units)
      if (same(u, n)) return f;
    fail_at(node, "unknown unit " + quoted(u) + " in <" + node.name() + ">");
  }

  void read_material(pugi::xml_node layer) {
    const pugi::xml_node m = layer.child("Material");
    if (!m) return;
    data_.material = trimmed(m.child("Name"));
    data_.manufacturer = trimmed(m.child("Manufacturer"));
    data_.device_type = trimmed(m.child("DeviceType"));
    auto length = [&](const char* tag) {
      const pugi::xml_node n = m.child(tag);
      if (!n) return 0.0;
      const double v = real(n) * meters(n);
      if (v < 0) fail_at(n, std::string("negative <") + tag + ">");
      return v;
    };
    data_.width = length("Width");
    data_.height = length("Height");
    data_.thickness = length("Thickness");
  }

  void read_geometry(pugi::xml_node layer) {
    const pugi::xml_node g = layer.child("Geometry");
    if (!g) return;
    if (pugi::xml_attribute f = g.attribute("format"); f && !same(f.value(), "MGF"))
      fail_at(g, "unsupported geometry format " + quoted(f.value()));
    const pugi::xml_node b = g.child("MGFblock");
    if (!b) return;
    const std::string mgf = text_of(b).value;
    const size_t start = detail::skip_space(mgf, 0);
    if (start == mgf.size()) return;
    data_.mgf = mgf.substr(start);
    data_.mgf_scale = meters(b);
  }

  void read_format(pugi::xml_node layer) {
    const pugi::xml_node n = layer.child("DataDefinition").child("IncidentDataStructure");
    const std::string s = trimmed(n);
    if (s.empty()) fail("missing <IncidentDataStructure>");
    if (same(s, "TensorTree3"))
      data_.format = Format::TensorTree3;
    else if (same(s, "TensorTree4"))
      data_.format = Format::TensorTree4;
    else if (same(s, "Columns") || same(s, "Rows"))
      data_.format = Format::Klems;
    else
      fail_at(n, "unsupported IncidentDataStructure " + quoted(s));
    rows_incident_ = same(s, "Rows");
  }

  // <AngleBasis> definitions. As in Radiance, a name already known (a built-in LBNL basis or
  // one defined earlier) keeps its definition, and the first ring starts at 0 whatever the
  // file's first LowerTheta says.
  void read_bases(pugi::xml_node def) {
    for (pugi::xml_node ab : def.children("AngleBasis")) {
      const std::string name = trimmed(ab.child("AngleBasisName"));
      if (name.empty() || find_basis(name)) continue;
      std::vector<double> theta{0};
      std::vector<int> nphis;
      for (pugi::xml_node blk : ab.children("AngleBasisBlock")) {
        const pugi::xml_node tb = blk.child("ThetaBounds");
        const pugi::xml_node upper = tb.child("UpperTheta");
        const pugi::xml_node np = blk.child("nPhis");
        if (!upper || !np)
          fail_at(blk, "missing <nPhis> or <UpperTheta> in angle basis " + quoted(name));
        if (!nphis.empty()) {
          const pugi::xml_node lower = tb.child("LowerTheta");
          const double lo = lower ? real(lower) : -1, prev = theta.back();
          if (std::fabs(lo - prev) > 1e-6 * std::fabs(prev))
            fail_at(blk, "theta bounds disagree in angle basis " + quoted(name));
        }
        theta.push_back(real(upper));
        nphis.push_back(integer(np));
      }
      try {
        bases_.emplace_back(name, std::move(theta), std::move(nphis));
      } catch (const FatalError& e) {
        fail_at(ab, e.what());
      }
    }
  }

  const KlemsBasis* find_basis(const std::string& name) const {
    for (const KlemsBasis& b : bases_)
      if (same(b.name(), name.c_str())) return &b;
    return KlemsBasis::standard(name);
  }

  const KlemsBasis& basis(pugi::xml_node block, const char* tag, const std::string& dir) const {
    const pugi::xml_node n = block.child(tag);
    const std::string name = trimmed(n);
    if (name.empty()) fail_at(block, std::string("missing <") + tag + "> for " + quoted(dir));
    const KlemsBasis* b = find_basis(name);
    if (!b) fail_at(n, "unknown angle basis " + quoted(name));
    return *b;
  }

  void read_wavelength_data(pugi::xml_node layer) {
    const bool klems = data_.format == Format::Klems;
    int blocks = 0;
    for (pugi::xml_node wd : layer.children("WavelengthData")) {
      ++blocks;
      const std::string wl = trimmed(wd.child("Wavelength"));
      std::optional<Channel> ch;
      // Klems colour comes as CIE X and Z, tensor-tree colour as u' and v' (as in Radiance).
      static const Channel klems_ch[] = {kY, kX, kZ}, tree_ch[] = {kY, kU, kV};
      for (Channel c : klems ? klems_ch : tree_ch)
        if (same(wl, kChannelNames[c])) ch = c;
      if (!ch) continue; // spectral or other data Radiance does not use
      for (pugi::xml_node blk : wd.children("WavelengthDataBlock"))
        read_block(blk, *ch);
    }
    if (blocks == 0) fail("no <WavelengthData>");
  }

  void read_block(pugi::xml_node blk, Channel ch) {
    const std::string dir = trimmed(blk.child("WavelengthDataDirection"));
    const PartName* pn = nullptr;
    for (const PartName& p : kParts)
      if (same(dir, p.file_name)) pn = &p;
    if (!pn) {
      warn("ignoring data with WavelengthDataDirection " + quoted(dir));
      return;
    }
    Pending& pd = pending(pn->part);
    if (pd.have[ch])
      warn("second " + quoted(kChannelNames[ch]) + " data for " + quoted(pn->file_name) +
           " replaces the first");
    pd.comp.direction = pn->file_name;
    if (ch == kY) pd.comp.scattering_type = trimmed(blk.child("ScatteringDataType"));

    const pugi::xml_node sd = blk.child("ScatteringData");
    const Text data = text_of(sd);
    if (detail::skip_space(data.value, 0) == data.value.size())
      fail_at(sd ? sd : blk, "missing <ScatteringData> for " + quoted(dir));
    if (data_.format == Format::Klems) {
      KlemsMatrix& m = pd.mtx[ch == kY ? 0 : ch == kX ? 1 : 2];
      m.in_basis = basis(blk, "ColumnAngleBasis", dir);
      m.out_basis = basis(blk, "RowAngleBasis", dir);
      m.y = matrix_values(data, m.in_basis.size(), m.out_basis.size(), dir);
    } else {
      const pugi::xml_node abn = blk.child("AngleBasis");
      const std::string ab = trimmed(abn);
      if (ab.empty()) fail_at(blk, "missing <AngleBasis> for " + quoted(dir));
      if (!same(ab, "LBNL/Shirley-Chiu"))
        fail_at(abn, "unknown angle basis " + quoted(ab) + " for a tensor tree");
      const int ndim = data_.format == Format::TensorTree3 ? 3 : 4;
      try {
        pd.tree[ch == kY ? 0 : ch == kU ? 1 : 2] = parse_tensor_tree(data.value, ndim);
      } catch (const TreeSyntaxError& e) {
        fail_at(data.offset + e.offset(), e.what() + (" for " + quoted(dir)));
      }
    }
    pd.have[ch] = true;
  }

  // The file's numbers, stored with the outgoing patch as the row (bsdf_data.h).
  std::vector<float> matrix_values(const Text& data, int nin, int nout, const std::string& dir) {
    const std::string& s = data.value;
    std::vector<float> vals(static_cast<size_t>(nin) * nout);
    size_t n = 0;
    for (size_t i = detail::skip_space(s, 0); i < s.size();) {
      double v;
      const size_t end = detail::scan_real(s, i, &v);
      if (end == std::string::npos ||
          (end < s.size() && !detail::is_space(s[end]) && s[end] != ','))
        fail_at(data.offset + i, "bad number " + quoted(std::string(detail::word_at(s, i))) +
                                     " in <ScatteringData> for " + quoted(dir));
      if (n < vals.size()) {
        // "Columns": each row of the file is one outgoing patch; "Rows": one incident patch.
        const size_t at = rows_incident_ ? (n % nout) * nin + n / nout : n;
        vals[at] = v < 0 ? 0.0f : static_cast<float>(v);
      }
      ++n;
      i = detail::skip_space(s, end);
      if (i < s.size() && s[i] == ',') i = detail::skip_space(s, i + 1);
    }
    if (n != vals.size())
      fail_at(data.offset, "<ScatteringData> for " + quoted(dir) + " has " + std::to_string(n) +
                               " values, not " + std::to_string(nout) + " x " +
                               std::to_string(nin) + " = " + std::to_string(vals.size()));
    return vals;
  }

  Pending& pending(Part part) {
    for (Pending& p : pending_)
      if (p.comp.part == part) return p;
    pending_.emplace_back();
    pending_.back().comp.part = part;
    pending_.back().comp.format = data_.format;
    return pending_.back();
  }

  // Assembles components: Y is required, colour needs both of its channels (and, for Klems,
  // the dimensions of Y); otherwise the component is grey, as in Radiance.
  void finish() {
    for (Pending& p : pending_) {
      Component& c = p.comp;
      const bool klems = data_.format == Format::Klems;
      const Channel c1 = klems ? kX : kU, c2 = klems ? kZ : kV;
      if (!p.have[kY]) {
        warn("ignoring " + quoted(c.direction) + ": it has no \"Visible\" data");
        continue;
      }
      bool colour = p.have[c1] && p.have[c2];
      if (klems && colour)
        colour = p.mtx[1].y.size() == p.mtx[0].y.size() && p.mtx[2].y.size() == p.mtx[0].y.size();
      if (!colour && (p.have[c1] || p.have[c2]))
        warn(quoted(c.direction) + " is grey: its " + kChannelNames[c1] + " and " +
             kChannelNames[c2] + " data are incomplete or of another size");
      if (klems) {
        c.klems = std::move(p.mtx[0]);
        if (colour) {
          c.klems.x = std::move(p.mtx[1].y);
          c.klems.z = std::move(p.mtx[2].y);
        }
      } else {
        c.tree.y = std::move(p.tree[0]);
        if (colour) {
          c.tree.u = std::move(p.tree[1]);
          c.tree.v = std::move(p.tree[2]);
        }
      }
      data_.components.push_back(std::move(c));
    }
    if (data_.components.empty()) fail("no \"Visible\" scattering data");
  }

  const std::string& text_;
  const std::string& name_;
  BsdfData data_;
  bool rows_incident_ = false;
  std::vector<KlemsBasis> bases_; // defined by the file
  std::vector<Pending> pending_;
};

} // namespace

BsdfData parse_bsdf_xml(const std::string& text, const std::string& name_for_messages) {
  return Reader(text, name_for_messages).read();
}

BsdfData read_bsdf_xml(const std::string& path) {
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) throw SystemError("cannot open BSDF file " + quoted(path) + ": " + std::strerror(errno));
  std::string text;
  char buf[65536];
  size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, f)) > 0)
    text.append(buf, n);
  const bool bad = std::ferror(f);
  const int err = errno;
  std::fclose(f);
  if (bad) throw SystemError("cannot read BSDF file " + quoted(path) + ": " + std::strerror(err));
  return parse_bsdf_xml(text, path);
}

} // namespace radcl::bsdf
