// Python binding of the Edge-Sharpener core: numpy arrays in, numpy arrays out.
// A thin layer: it checks the arrays, builds a vcg mesh, runs the core with the
// GIL released and converts the result. Keywords, defaults, ranges and the
// docstrings come from the shared option table (option_table.h), the report
// from the CLI's JSON (report_json.h).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <chrono>
#include <climits>
#include <cmath>
#include <cstdint>
#include <exception>
#include <sstream>
#include <string>
#include <vector>

#include "edge_sharpener/edge_sharpener.h"
#include "edge_sharpener/option_table.h"
#include "edge_sharpener/restored_edges.h"
#include "edge_sharpener/util/mesh_types.h"
#include "mesh_distance.h"
#include "report_json.h"

namespace py = pybind11;
namespace es = edge_sharpener;

namespace {

// ---------------------------------------------------------------- input arrays

/// The caller's arrays after their checks: C-contiguous copies or views in the
/// dtype the mesh is built from. The caller's arrays are only read.
template <class Real>
struct CheckedArrays {
  py::array_t<Real, py::array::c_style | py::array::forcecast> vertices;
  py::array_t<std::int64_t, py::array::c_style | py::array::forcecast> faces;
};

std::string shapeText(const py::array &a) {
  std::ostringstream s;
  s << "(";
  for (py::ssize_t i = 0; i < a.ndim(); ++i) s << (i ? ", " : "") << a.shape(i);
  s << (a.ndim() == 1 ? ",)" : ")");
  return s.str();
}

std::string dtypeText(const py::array &a) {
  return py::str(a.dtype()).cast<std::string>();
}

void requireRows3(const py::array &a, const char *name) {
  if (a.ndim() != 2 || a.shape(1) != 3)
    throw es::InputError(std::string(name) + " must be an array of shape (n, 3), got shape " +
                         shapeText(a));
}

/// `value` as a numpy array (lists and other array-likes too), without copying an array.
py::array asArray(const py::handle &value, const char *name) {
  try {
    return py::module_::import("numpy").attr("asarray")(value);
  } catch (py::error_already_set &error) {
    if (!error.matches(PyExc_ValueError) && !error.matches(PyExc_TypeError)) throw;
    throw es::InputError(std::string(name) + " must be an array of shape (n, 3): " +
                         py::str(error.value()).cast<std::string>());
  }
}

bool isFloat32(const py::array &vertices) {
  return vertices.dtype().kind() == 'f' && vertices.itemsize() == 4;
}

/// Checks shapes, dtypes and indices (what the core cannot see once the mesh
/// is built: a bad index would be a dangling pointer). Coordinates are checked
/// by the core (findInputProblem).
template <class Real>
CheckedArrays<Real> checkArrays(const py::array &vertices, const py::array &faces,
                                const char *prefix = "") {
  const std::string v = std::string(prefix) + "vertices", f = std::string(prefix) + "faces";
  requireRows3(vertices, v.c_str());
  requireRows3(faces, f.c_str());
  const char vk = vertices.dtype().kind(), fk = faces.dtype().kind();
  if (vk != 'f' || (vertices.itemsize() != 4 && vertices.itemsize() != 8))
    throw es::InputError(v + " must hold float32 or float64 numbers, got " + dtypeText(vertices));
  if (fk != 'i' && fk != 'u')
    throw es::InputError(f + " must hold integers, got " + dtypeText(faces));
  if (vertices.shape(0) >= INT_MAX || faces.shape(0) >= INT_MAX)
    throw es::InputError("too many " + (vertices.shape(0) >= INT_MAX ? v : f) +
                         " for a vcg mesh (at most 2^31 - 2)");
  // An unsigned index above INT64_MAX would wrap in the int64 copy: refuse it first.
  if (fk == 'u' && faces.itemsize() == 8 && faces.size() > 0) {
    const py::object largest = faces.attr("max")();
    if (largest.cast<std::uint64_t>() > std::uint64_t(INT64_MAX))
      throw es::InputError(f + " has vertex index " + py::str(largest).cast<std::string>() +
                           " out of range [0, " + std::to_string(vertices.shape(0)) + ")");
  }
  CheckedArrays<Real> out{
      py::array_t<Real, py::array::c_style | py::array::forcecast>(vertices),
      py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>(faces)};
  const std::int64_t nv = vertices.shape(0);
  const std::int64_t *index = out.faces.data();
  for (py::ssize_t i = 0; i < out.faces.size(); ++i)
    if (index[i] < 0 || index[i] >= nv)
      throw es::InputError("face " + std::to_string(i / 3) + " has vertex index " +
                           std::to_string(index[i]) + " out of range [0, " + std::to_string(nv) +
                           ")");
  return out;
}

/// Builds `m` from checked arrays (fresh, hence compact, as the core requires).
/// Reserves twice the counts first, as the command line does
/// (apps/capacity_hint.h): the subdivision then appends without reallocating
/// the arrays (and moving every pointer); unwritten capacity is only address
/// space.
template <class MeshType, class Real>
void buildMesh(const CheckedArrays<Real> &arrays, MeshType &m) {
  using Alloc = vcg::tri::Allocator<MeshType>;
  using Scalar = typename MeshType::ScalarType;
  const std::size_t nv = std::size_t(arrays.vertices.shape(0));
  const std::size_t nf = std::size_t(arrays.faces.shape(0));
  const Real *xyz = arrays.vertices.data();
  const std::int64_t *index = arrays.faces.data();
  m.vert.reserve(2 * nv);
  m.face.reserve(2 * nf);
  if (nv > 0) Alloc::AddVertices(m, nv);
  for (std::size_t i = 0; i < nv; ++i)
    m.vert[i].P() = {Scalar(xyz[3 * i]), Scalar(xyz[3 * i + 1]), Scalar(xyz[3 * i + 2])};
  if (nf > 0) Alloc::AddFaces(m, nf);
  for (std::size_t i = 0; i < nf; ++i)
    for (int k = 0; k < 3; ++k) m.face[i].V(k) = &m.vert[std::size_t(index[3 * i + k])];
}

/// Checks `face_mask` (None: none): a boolean array of shape (m,), m the
/// face count. \return per face, selected or not (empty for None).
std::vector<char> checkFaceMask(const py::object &mask, py::ssize_t faceCount) {
  if (mask.is_none()) return {};
  const py::array a = asArray(mask, "face_mask");
  if (a.ndim() != 1 || a.shape(0) != faceCount)
    throw es::InputError("face_mask must be an array of shape (" + std::to_string(faceCount) +
                         ",), one bool per face, got shape " + shapeText(a));
  if (a.dtype().kind() != 'b')
    throw es::InputError("face_mask must hold booleans, got " + dtypeText(a) +
                         " (numpy.asarray(mask, dtype=bool) makes one)");
  const py::array_t<bool, py::array::c_style | py::array::forcecast> values(a);
  return std::vector<char>(values.data(), values.data() + faceCount);
}

/// Checks `vertex_colors` (None: none): an (n, 3) or (n, 4) array, n the
/// vertex count, of integers in [0, 255] or floats in [0, 1]. \return RGBA
/// bytes, 4 per vertex (alpha 255 where absent; empty for None).
std::vector<std::uint8_t> checkVertexColors(const py::object &colors, py::ssize_t vertexCount) {
  if (colors.is_none()) return {};
  const py::array a = asArray(colors, "vertex_colors");
  const std::string shapeText = py::str(a.attr("shape")).cast<std::string>();
  if (a.ndim() != 2 || a.shape(0) != vertexCount || (a.shape(1) != 3 && a.shape(1) != 4))
    throw es::InputError("vertex_colors must be an array of shape (" + std::to_string(vertexCount) +
                         ", 3) or (" + std::to_string(vertexCount) +
                         ", 4), one row per vertex, got shape " + shapeText);
  const char kind = a.dtype().kind();
  if (kind != 'u' && kind != 'i' && kind != 'f')
    throw es::InputError("vertex_colors must hold integers in [0, 255] or floats in [0, 1], got " +
                         dtypeText(a));
  const py::array_t<double, py::array::c_style | py::array::forcecast> values(a);
  const double scale = kind == 'f' ? 255.0 : 1.0, top = kind == 'f' ? 1.0 : 255.0;
  const py::ssize_t columns = a.shape(1);
  std::vector<std::uint8_t> rgba(std::size_t(4 * vertexCount), 255);
  const double *x = values.data();
  for (py::ssize_t i = 0; i < vertexCount; ++i)
    for (py::ssize_t c = 0; c < columns; ++c) {
      const double value = x[i * columns + c];
      if (!(value >= 0 && value <= top))  // NaN too
        throw es::InputError("vertex_colors row " + std::to_string(i) + " has value " +
                             py::str(py::float_(value)).cast<std::string>() + " outside [0, " +
                             (kind == 'f' ? "1" : "255") + "]");
      rgba[std::size_t(4 * i + c)] = std::uint8_t(std::lround(value * scale));
    }
  return rgba;
}

/// The vertices' colours as (n, 4) uint8 RGBA rows.
template <class MeshType>
py::array_t<std::uint8_t> vertexColourRows(const MeshType &m) {
  py::array_t<std::uint8_t> rows({py::ssize_t(m.vert.size()), py::ssize_t(4)});
  auto out = rows.mutable_unchecked<2>();
  for (std::size_t i = 0; i < m.vert.size(); ++i)
    for (int c = 0; c < 4; ++c) out(i, c) = m.vert[i].cC()[c];
  return rows;
}

/// The attribute sharpen() records the restored vertices in
/// (restored_edges.h), added for one call and deleted however it ends.
template <class MeshType>
class RestoredVertices {
 public:
  explicit RestoredVertices(MeshType &m)
      : m_(m),
        h_(vcg::tri::Allocator<MeshType>::template AddPerVertexAttribute<std::uint8_t>(
            m, es::kRestoredVertexAttribute)) {}
  ~RestoredVertices() { vcg::tri::Allocator<MeshType>::DeletePerVertexAttribute(m_, h_); }
  RestoredVertices(const RestoredVertices &) = delete;
  RestoredVertices &operator=(const RestoredVertices &) = delete;

  /// Into the report: "restored_vertices" (int64 indices) and "sharp_edges"
  /// ((k, 2) int64, the faces' index type), the edges joining two of them.
  void report(py::dict &out) {
    std::vector<std::uint8_t> restored(m_.vert.size());
    std::vector<std::int64_t> indices;
    for (std::size_t v = 0; v < m_.vert.size(); ++v)
      if ((restored[v] = h_[v])) indices.push_back(std::int64_t(v));
    const auto edges = es::restoredEdges(m_, restored);
    py::array_t<std::int64_t> vertexArray(py::ssize_t(indices.size()));
    std::copy(indices.begin(), indices.end(), vertexArray.mutable_data());
    py::array_t<std::int64_t> edgeArray({py::ssize_t(edges.size()), py::ssize_t(2)});
    std::int64_t *e = edgeArray.mutable_data();
    for (const auto &[a, b] : edges) *e++ = a, *e++ = b;
    out["restored_vertices"] = vertexArray;
    out["sharp_edges"] = edgeArray;
  }

 private:
  MeshType &m_;
  typename MeshType::template PerVertexAttributeHandle<std::uint8_t> h_;
};

template <class MeshType>
py::tuple meshArrays(const MeshType &m) {
  using Scalar = typename MeshType::ScalarType;
  const py::ssize_t nv = py::ssize_t(m.vert.size()), nf = py::ssize_t(m.face.size());
  py::array_t<Scalar> vertices({nv, py::ssize_t(3)});
  py::array_t<std::int64_t> faces({nf, py::ssize_t(3)});
  Scalar *xyz = vertices.mutable_data();
  for (py::ssize_t i = 0; i < nv; ++i)
    for (int c = 0; c < 3; ++c) xyz[3 * i + c] = m.vert[i].cP()[c];
  std::int64_t *index = faces.mutable_data();
  for (py::ssize_t i = 0; i < nf; ++i)
    for (int k = 0; k < 3; ++k) index[3 * i + k] = m.face[i].cV(k) - m.vert.data();
  return py::make_tuple(vertices, faces);
}

// ---------------------------------------------------------------- options

const char *typeName(es::OptionType type) {
  switch (type) {
    case es::OptionType::Flag: return "flag";
    case es::OptionType::Integer: return "integer";
    case es::OptionType::Real: return "real";
    case es::OptionType::Choice: return "choice";
  }
  return "";
}

/// A table value as Python shows it: bool, int, float or the choice's name.
py::object pythonValue(const es::OptionSpec &spec, double value) {
  switch (spec.type) {
    case es::OptionType::Flag: return py::bool_(value != 0);
    case es::OptionType::Integer: return py::int_(int(value));
    case es::OptionType::Choice: return py::str(std::string(spec.choiceName(value)));
    case es::OptionType::Real: break;
  }
  return py::float_(value);
}

/// The option's value as the table holds it (choices by index).
/// \throws TypeError for a value of the wrong kind, InputError for a value out
///         of range or an unknown choice.
double optionValue(const es::OptionSpec &spec, const py::object &value) {
  const std::string key(spec.key);
  double number = 0;
  if (spec.type == es::OptionType::Choice) {
    std::string names;
    for (std::string_view c : spec.choices)
      names += (names.empty() ? "'" : ", '") + std::string(c) + "'";
    if (!py::isinstance<py::str>(value))
      throw py::type_error("option " + key + " must be one of " + names);
    const int index = spec.choiceIndex(value.cast<std::string>());
    if (index < 0)
      throw es::InputError("option " + key + " has no such choice '" + value.cast<std::string>() +
                           "' (" + names + ")");
    number = index;
  } else {
    // Strings would convert through float(): refuse them as the wrong kind.
    if (py::isinstance<py::str>(value) || py::isinstance<py::bytes>(value))
      throw py::type_error("option " + key + " must be a number, got " +
                           py::str(value.get_type().attr("__name__")).cast<std::string>());
    try {
      number = value.cast<py::float_>().cast<double>();
    } catch (const py::error_already_set &) {
      throw py::type_error("option " + key + " must be a number, got " +
                           py::str(value.get_type().attr("__name__")).cast<std::string>());
    } catch (const py::cast_error &) {
      throw py::type_error("option " + key + " must be a number, got " +
                           py::str(value.get_type().attr("__name__")).cast<std::string>());
    }
  }
  const std::string problem = spec.problemWith(number);
  if (!problem.empty()) throw es::InputError(problem);
  return number;
}

/// The tuning options' keys close to `key` ("; did you mean 'x'?"), or empty.
std::string closeTuningKeys(const std::string &key) {
  py::list keys;
  for (const es::OptionSpec &spec : es::optionTable())
    if (!spec.ordinary()) keys.append(std::string(spec.key));
  const py::list close = py::module_::import("difflib").attr("get_close_matches")(key, keys, 2);
  std::string out;
  for (const py::handle &c : close)
    out += (out.empty() ? "; did you mean '" : "' or '") + c.cast<std::string>();
  return out.empty() ? out : out + "'?";
}

/// The core's options: its defaults, then the ordinary options given as
/// keywords and each method's tuning given in the `tuning` mapping (None:
/// none), in table order.
/// \throws TypeError for an unknown keyword (a tuning option's names where it
///         goes), a `tuning` that is no mapping or a value of the wrong kind;
///         InputError for an unknown or ordinary key in `tuning`, a value out
///         of range or an unknown choice.
es::SharpenOptions optionsFrom(const py::kwargs &given, const py::object &tuningArg,
                               const char *function) {
  for (const auto &item : given) {
    const std::string key = py::str(item.first);
    const es::OptionSpec *spec = es::findOption(key);
    if (spec && !spec->ordinary())
      throw py::type_error(std::string(function) + "() got an unexpected keyword argument '" + key +
                           "': a tuning option goes in the tuning dict, tuning={'" + key +
                           "': ...}");
    if (!spec)
      throw py::type_error(std::string(function) + "() got an unexpected keyword argument '" + key +
                           "'");
  }
  py::dict tuning;
  if (!tuningArg.is_none()) {
    if (!py::isinstance(tuningArg, py::module_::import("collections.abc").attr("Mapping")))
      throw py::type_error(
          "tuning must be a dict of tuning options ({'max_label_hops': 4, ...}), "
          "got " +
          py::str(tuningArg.get_type().attr("__name__")).cast<std::string>());
    tuning = py::dict(tuningArg);
    for (const auto &item : tuning) {
      const std::string key = py::str(item.first);
      const es::OptionSpec *spec =
          py::isinstance<py::str>(item.first) ? es::findOption(key) : nullptr;
      if (spec && spec->ordinary())
        throw es::InputError("'" + key + "' is no tuning option: give it as the keyword argument " +
                             key + "=...");
      if (!spec)
        throw es::InputError("unknown tuning option '" + key + "'" + closeTuningKeys(key) +
                             " (help(edge_sharpener.sharpen) lists them)");
    }
  }
  es::SharpenOptions opt;
  for (const es::OptionSpec &spec : es::optionTable()) {
    const std::string key(spec.key);
    const py::dict &source = spec.ordinary() ? static_cast<const py::dict &>(given) : tuning;
    if (source.contains(key)) spec.set(opt, optionValue(spec, source[key.c_str()]));
  }
  return opt;
}

/// `text` as lines of at most 88 columns, each starting with `indent`.
std::string wrapped(const std::string &text, const std::string &indent) {
  std::istringstream words(text);
  std::string word, out, line;
  while (words >> word) {
    if (!line.empty() && indent.size() + line.size() + 1 + word.size() > 88) {
      out += indent + line + "\n";
      line.clear();
    }
    line += (line.empty() ? "" : " ") + word;
  }
  if (!line.empty()) out += indent + line + "\n";
  return out;
}

/// One option in a docstring: "    multiplier: real in (0, 100] x mean normal angle, default 2".
std::string optionDoc(const es::OptionSpec &spec) {
  std::ostringstream s;
  s << "    " << spec.key << ": ";
  if (spec.type == es::OptionType::Choice) {
    for (std::size_t i = 0; i < spec.choices.size(); ++i)
      s << (i ? " or '" : "'") << spec.choices[i] << "'";
    s << ", default '" << spec.choiceName(spec.defaultValue()) << "'";
  } else if (spec.type == es::OptionType::Flag) {
    s << "bool, default " << (spec.defaultValue() != 0 ? "True" : "False");
  } else {
    s << typeName(spec.type) << " in " << (spec.minExclusive ? "(" : "[") << spec.minValue << ", "
      << spec.maxValue << "]";
    if (!spec.unit.empty()) s << " " << spec.unit;
    s << ", default " << spec.defaultValue();
  }
  s << "\n" << wrapped(std::string(spec.label) + ". " + std::string(spec.help), "        ");
  return s.str();
}

/// Every option of the table by group, for the docstrings of sharpen() and
/// detect(): the ordinary ones (keyword arguments), then each method's tuning
/// (the `tuning` dict).
std::string optionsDoc() {
  std::string doc;
  const char *group = nullptr;
  bool tuningSaid = false;
  for (const es::OptionSpec &spec : es::optionTable()) {
    if (group != es::toString(spec.group)) {
      if (!spec.ordinary() && !tuningSaid) {
        doc += "\n" + wrapped(
                          "Each method's tuning goes in the tuning dict, e.g. "
                          "tuning={'max_label_hops': 4, 'min_feature_vertices': 5}; an unknown key "
                          "raises InputError.",
                          "");
        tuningSaid = true;
      }
      group = es::toString(spec.group);
      doc += std::string("\n") + group + (spec.ordinary() ? " (keyword arguments):\n" : ":\n");
    }
    doc += optionDoc(spec);
  }
  return doc;
}

/// The table as Python data (module attribute OPTIONS): what the Blender
/// add-on builds its panel from.
py::tuple optionRecords() {
  py::list records;
  for (const es::OptionSpec &spec : es::optionTable()) {
    py::dict r;
    r["key"] = std::string(spec.key);
    r["label"] = std::string(spec.label);
    r["cli_flag"] = std::string(spec.cliFlag);
    r["help"] = std::string(spec.help);
    r["type"] = typeName(spec.type);
    r["group"] = es::toString(spec.group);
    r["ordinary"] = spec.ordinary();
    r["unit"] = std::string(spec.unit);
    r["min"] = spec.minValue;
    r["max"] = spec.maxValue;
    r["min_exclusive"] = spec.minExclusive;
    py::list choices;
    for (std::string_view c : spec.choices) choices.append(std::string(c));
    r["choices"] = py::tuple(choices);
    r["default"] = pythonValue(spec, spec.defaultValue());
    records.append(r);
  }
  return py::tuple(records);
}

// ---------------------------------------------------------------- progress

/// vcg's callback is a plain function pointer: the Python callable of the
/// running call is reached through a thread-local (the core reports progress
/// from the thread that called it, between its parallel loops).
struct PythonProgress {
  py::object callback;
  std::exception_ptr error;  ///< raised by the callback; rethrown when the core returns
};
thread_local PythonProgress *activeProgress = nullptr;

bool callPythonProgress(const int percent, const char *stage) {
  PythonProgress *p = activeProgress;
  if (!p || p->error) return true;
  py::gil_scoped_acquire gil;
  try {
    p->callback(percent, stage);
  } catch (...) {
    p->error = std::current_exception();
  }
  return true;
}

/// Runs `work` with the GIL released and `callback` (or None) as progress.
template <class Work>
void runWithoutGil(const py::object &callback, es::SharpenOptions &opt, Work &&work) {
  PythonProgress progress{callback, nullptr};
  // Restored on the way out: a callback may itself call sharpen().
  PythonProgress *const outer = activeProgress;
  if (!callback.is_none()) {
    if (!PyCallable_Check(callback.ptr())) throw py::type_error("progress must be callable");
    opt.progress = callPythonProgress;
    activeProgress = &progress;
  }
  try {
    py::gil_scoped_release release;
    work();
  } catch (...) {
    activeProgress = outer;
    throw;
  }
  activeProgress = outer;
  if (progress.error) std::rethrow_exception(progress.error);
}

// ---------------------------------------------------------------- JSON -> Python

py::object toPython(const nlohmann::json &j) {
  switch (j.type()) {
    case nlohmann::json::value_t::object: {
      py::dict d;
      for (const auto &[key, value] : j.items()) d[py::str(key)] = toPython(value);
      return d;
    }
    case nlohmann::json::value_t::array: {
      py::list l;
      for (const auto &value : j) l.append(toPython(value));
      return l;
    }
    case nlohmann::json::value_t::string: return py::str(j.get<std::string>());
    case nlohmann::json::value_t::boolean: return py::bool_(j.get<bool>());
    case nlohmann::json::value_t::number_integer: return py::int_(j.get<std::int64_t>());
    case nlohmann::json::value_t::number_unsigned: return py::int_(j.get<std::uint64_t>());
    case nlohmann::json::value_t::number_float: return py::float_(j.get<double>());
    default: return py::none();
  }
}

// ---------------------------------------------------------------- entry points

template <class MeshType, class Real>
py::tuple sharpenAs(const py::array &vertices, const py::array &faces, const py::object &progress,
                    const py::object &vertexColors, const py::object &faceMask,
                    es::SharpenOptions opt) {
  const CheckedArrays<Real> arrays = checkArrays<Real>(vertices, faces);
  const std::vector<std::uint8_t> rgba = checkVertexColors(vertexColors, vertices.shape(0));
  const std::vector<char> selected = checkFaceMask(faceMask, faces.shape(0));
  MeshType m;
  buildMesh(arrays, m);
  if (!selected.empty()) {
    for (std::size_t i = 0; i < selected.size(); ++i)
      if (selected[i]) m.face[i].SetS();
    opt.selectedFacesOnly = true;
  }
  for (std::size_t i = 0; 4 * i < rgba.size(); ++i)
    m.vert[i].C() = vcg::Color4b(rgba[4 * i], rgba[4 * i + 1], rgba[4 * i + 2], rgba[4 * i + 3]);
  RestoredVertices<MeshType> restored(m);
  es::SharpenReport report;
  const auto start = std::chrono::steady_clock::now();
  runWithoutGil(progress, opt, [&] { report = es::sharpen(m, opt); });
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  nlohmann::json j = es::reportToJson(report);
  j["options"] = es::optionsToJson(opt);
  j["seconds"] = seconds;
  py::dict reportDict = toPython(j);
  if (opt.colorize) {
    // The colours are the labels painted (colorize.h): returned as RGBA rows.
    py::array_t<std::uint8_t> faceColors({py::ssize_t(m.face.size()), py::ssize_t(4)});
    auto fc = faceColors.mutable_unchecked<2>();
    for (std::size_t i = 0; i < m.face.size(); ++i)
      for (int c = 0; c < 4; ++c) fc(i, c) = m.face[i].cC()[c];
    py::dict colors;
    colors["faces"] = faceColors;
    colors["vertices"] = vertexColourRows(m);
    reportDict["colors"] = colors;
  }
  // Each new vertex took the mean colour of the vertices it was made between
  // (subdivide()); colorize paints over them.
  if (!rgba.empty()) reportDict["vertex_colors"] = vertexColourRows(m);
  restored.report(reportDict);
  const py::tuple out = meshArrays(m);
  return py::make_tuple(out[0], out[1], reportDict);
}

py::tuple sharpen(const py::object &vertexData, const py::object &faceData,
                  const py::object &progress, const py::object &vertexColors,
                  const py::object &faceMask, const py::object &tuning, const py::kwargs &options) {
  const es::SharpenOptions opt = optionsFrom(options, tuning, "sharpen");
  const py::array vertices = asArray(vertexData, "vertices"), faces = asArray(faceData, "faces");
  requireRows3(vertices, "vertices");
  return isFloat32(vertices)
             ? sharpenAs<es::Mesh, float>(vertices, faces, progress, vertexColors, faceMask, opt)
             : sharpenAs<es::MeshD, double>(vertices, faces, progress, vertexColors, faceMask, opt);
}

template <class MeshType, class Real>
py::array detectAs(const py::array &vertices, const py::array &faces, const py::object &progress,
                   es::SharpenOptions opt) {
  const CheckedArrays<Real> arrays = checkArrays<Real>(vertices, faces);
  MeshType m;
  buildMesh(arrays, m);
  // The labels, read back from the paper palette's colours below; the auto
  // method's are the extended method's (the same zones), found without its
  // run on a copy.
  es::SharpenOptions labelled = opt;
  labelled.colors = es::ColorScheme::Paper;
  if (labelled.method == es::Method::Auto) labelled.method = es::Method::Extended;
  runWithoutGil(progress, labelled, [&] { es::detectChamfers(m, labelled); });
  // detectChamfers() keeps its labels in scoped attributes, gone when it
  // returns; the face colours it paints (colorize.h) are their public form.
  const es::FaceLabel kLabels[] = {es::FaceLabel::Gray, es::FaceLabel::Red, es::FaceLabel::Chamfer,
                                   es::FaceLabel::Corner};
  py::array_t<std::uint8_t> labels(py::ssize_t(m.face.size()));
  std::uint8_t *out = labels.mutable_data();
  for (std::size_t i = 0; i < m.face.size(); ++i) {
    out[i] = 0;
    for (es::FaceLabel l : kLabels)
      if (m.face[i].cC() == es::faceLabelColor(l)) out[i] = std::uint8_t(l);
  }
  return labels;
}

py::array detect(const py::object &vertexData, const py::object &faceData,
                 const py::object &progress, const py::object &tuning, const py::kwargs &options) {
  const es::SharpenOptions opt = optionsFrom(options, tuning, "detect");
  const py::array vertices = asArray(vertexData, "vertices"), faces = asArray(faceData, "faces");
  requireRows3(vertices, "vertices");
  return isFloat32(vertices) ? detectAs<es::Mesh, float>(vertices, faces, progress, opt)
                             : detectAs<es::MeshD, double>(vertices, faces, progress, opt);
}

py::dict oneSided(const es::OneSidedDistance &d, const es::DistanceReport &r) {
  py::dict out;
  out["min"] = d.min;
  out["max"] = d.max;
  out["mean"] = d.mean;
  out["rms"] = d.rms;
  out["samples"] = d.samples;
  out["min_percent"] = r.percentOfDiagonal(d.min);
  out["max_percent"] = r.percentOfDiagonal(d.max);
  out["mean_percent"] = r.percentOfDiagonal(d.mean);
  out["rms_percent"] = r.percentOfDiagonal(d.rms);
  return out;
}

/// Refuses what mesh-distance refuses (no faces, non-finite coordinates).
template <class MeshType>
void requireMeasurable(const MeshType &m, const char *name) {
  if (m.face.empty()) throw es::InputError(std::string(name) + " mesh has no faces");
  for (const auto &v : m.vert)
    for (int c = 0; c < 3; ++c)
      if (!std::isfinite(v.cP()[c]))
        throw es::InputError(std::string(name) + " mesh has NaN or infinite vertex coordinates");
}

template <class MeshType, class Real>
py::dict distanceAs(const py::array &av, const py::array &af, const py::array &bv,
                    const py::array &bf, const es::DistanceOptions &options) {
  MeshType a, b;
  buildMesh(checkArrays<Real>(av, af, "a_"), a);
  buildMesh(checkArrays<Real>(bv, bf, "b_"), b);
  requireMeasurable(a, "a");
  requireMeasurable(b, "b");
  es::DistanceReport r;
  {
    py::gil_scoped_release release;
    try {
      r = es::measureDistance(a, b, options);
    } catch (const std::invalid_argument &e) {
      throw es::InputError(e.what());
    }
  }
  py::dict out, sampled, symmetric;
  out["reference_diagonal"] = r.referenceDiagonal;
  out["sampling"] = es::distanceSamplingName(options.sampling);
  out["face_samples"] = options.faceSamples;
  out["seed"] = options.seed;
  sampled["vertices"] = options.sampleVertices;
  sampled["edges"] = options.sampleEdges;
  sampled["faces"] = options.sampleFaces;
  out["sampled"] = sampled;
  out["forward"] = oneSided(r.forward, r);
  out["backward"] = oneSided(r.backward, r);
  symmetric["max"] = r.max();
  symmetric["mean"] = r.mean();
  symmetric["rms"] = r.rms();
  symmetric["max_percent"] = r.maxPercent();
  symmetric["mean_percent"] = r.meanPercent();
  symmetric["rms_percent"] = r.rmsPercent();
  out["symmetric"] = symmetric;
  return out;
}

py::dict meshDistance(const py::object &aVertices, const py::object &aFaces,
                      const py::object &bVertices, const py::object &bFaces, long long samples,
                      const py::object &seedArg, bool sampleVertices, bool sampleEdges,
                      const std::string &sampling) {
  if (samples < 1 || samples > 1000000000)
    throw es::InputError("samples must be in [1, 1000000000]");
  if (sampling != "uniform" && sampling != "meshlab")
    throw es::InputError("sampling must be 'uniform' or 'meshlab'");
  // As mesh-distance: MeshLab's mode starts where a fresh MeshLab's generator does.
  const long long seed = seedArg.is_none() ? (sampling == "meshlab" ? es::kMeshLabSeed : 1)
                                           : seedArg.cast<long long>();
  if (seed < 0 || seed > UINT_MAX) throw es::InputError("seed must be in [0, 2^32 - 1]");
  const py::array av = asArray(aVertices, "a_vertices"), af = asArray(aFaces, "a_faces");
  const py::array bv = asArray(bVertices, "b_vertices"), bf = asArray(bFaces, "b_faces");
  es::DistanceOptions options;
  options.sampling =
      sampling == "meshlab" ? es::DistanceSampling::meshlab : es::DistanceSampling::uniform;
  options.faceSamples = std::size_t(samples);
  options.seed = unsigned(seed);
  options.sampleVertices = sampleVertices;
  options.sampleEdges = sampleEdges;
  requireRows3(av, "a_vertices");
  requireRows3(bv, "b_vertices");
  // Both meshes in one precision: single when both are float32 (as mesh-distance reads them).
  return isFloat32(av) && isFloat32(bv) ? distanceAs<es::Mesh, float>(av, af, bv, bf, options)
                                        : distanceAs<es::MeshD, double>(av, af, bv, bf, options);
}

}  // namespace

PYBIND11_MODULE(_edge_sharpener, m) {
  m.doc() =
      "Edge-Sharpener (Attene et al. 2003): restores the sharp edges and corners that marching "
      "cubes, voxel remeshers and uniform resamplings cut into chamfers.";
  py::register_exception<es::InputError>(m, "InputError", PyExc_ValueError);
  m.attr("InputError").attr("__doc__") =
      "The mesh, the arrays or an option cannot be processed (the message says why).";

  static const std::string options = optionsDoc();
  static const std::string arraysDoc =
      wrapped(
          "vertices: (n, 3) float32 or float64 array. float32 is processed in single "
          "precision (exactly like the edge-sharpener CLI), float64 in double precision; the "
          "result has the same dtype.",
          "") +
      wrapped(
          "faces: (m, 3) integer array of vertex indices (a consistently oriented, manifold "
          "triangle mesh; boundaries allowed).",
          "") +
      wrapped(
          "progress: optional callable(percent: int, stage: str), called between stages "
          "(its return value is ignored; an exception it raises is raised when the run "
          "ends).",
          "") +
      wrapped(
          "The caller's arrays are never modified. The GIL is released while the core runs. "
          "Raises InputError (a ValueError) with the core's message on bad input, an "
          "option out of range or an unknown key in `tuning`, TypeError on an unknown keyword "
          "or a value of the wrong kind.",
          "");
  static const std::string sharpenDoc =
      "sharpen(vertices, faces, *, progress=None, vertex_colors=None, face_mask=None, "
      "tuning=None, **options) -> (vertices, faces, report)\n\n" +
      wrapped(
          "Detects chamfers and corners and sharpens them. Original vertices keep their "
          "index (with the paper method also their position: the others move the feature "
          "zone's vertices onto their planes, and the auto method flattens the planar faces "
          "of a rough input it leaves whole); inserted vertices follow them. Returns new "
          "arrays: vertices "
          "(n', 3) of the input's float dtype, faces (m', 3) int64, and `report`, a dict with "
          "the content of the CLI's --json report (each stage's counts, 'options' as used, "
          "'seconds', 'summary': what was restored and left, in one line, as the CLI prints "
          "it); with colorize=True it also holds 'colors': {'faces': (m', 4) uint8 "
          "RGBA, 'vertices': (n', 4) uint8 RGBA}. vertex_colors, an (n, 3) or (n, 4) array "
          "of integers in [0, 255] or floats in [0, 1], gives the input's colours: the report "
          "then holds 'vertex_colors', (n', 4) uint8 RGBA, each new vertex with the mean "
          "colour of the vertices it was made between (with colorize=True, the labels' "
          "colours). The report's 'restored_vertices' (int64) are the output vertices placed "
          "on a sharp edge or corner, and 'sharp_edges' ((k, 2) int64) the output edges "
          "joining two of them: the restored feature lines (to mark sharp for shading, or "
          "select).",
          "") +
      wrapped(
          "face_mask, an (m,) bool array, sharpens only within the faces it selects (as "
          "MeshLab's 'Affect only selected faces'): every feature is judged as without it, "
          "then a new vertex on a face outside it stays at rest, so a feature it cuts is "
          "sharpened up to its border and a feature wholly outside is left (report verdict "
          "'outside_selection'); the paper and extended methods split and move nothing outside "
          "it. No face selected: the mesh comes back as it was (report 'summary' says so).",
          "") +
      "\n" + arraysDoc + options;
  static const std::string detectDoc =
      "detect(vertices, faces, *, progress=None, tuning=None, **options) -> labels\n\n" +
      wrapped(
          "Runs detection only (no geometry change): a uint8 label per face, an index into "
          "FACE_LABELS: 0 other, 1 smooth region, 2 chamfer, 3 corner. The auto method's "
          "verdict on each feature, and the faces it owns, are in sharpen()'s report "
          "('features').",
          "") +
      "\n" + arraysDoc + options;
  static const std::string distanceDoc =
      "mesh_distance(a_vertices, a_faces, b_vertices, b_faces, *, samples=200000, seed=None, "
      "sample_vertices=True, sample_edges=True, sampling='uniform') -> dict\n\n" +
      wrapped(
          "Two-sided (Metro) surface distance between mesh A and the reference mesh B, as "
          "the mesh-distance tool's --json: 'forward' (A sampled, measured against B), "
          "'backward', 'symmetric' (max = Hausdorff distance, mean, rms), each also in "
          "percent of B's bounding-box diagonal ('reference_diagonal'). `samples` points are "
          "spread over each mesh's faces by area (edges get a quarter as many); a fixed "
          "`seed` makes the result deterministic. Both meshes are measured in single "
          "precision when both vertex arrays are float32 (as mesh-distance does), else in "
          "double precision. sampling='meshlab' spreads the samples as MeshLab's Hausdorff "
          "Distance filter does (seed None: 5489, a fresh MeshLab's; 'uniform': 1); the dict "
          "names the mode in 'sampling'. Raises InputError on bad input.",
          "");

  m.def("sharpen", &sharpen, sharpenDoc.c_str(), py::arg("vertices"), py::arg("faces"),
        py::kw_only(), py::arg("progress") = py::none(), py::arg("vertex_colors") = py::none(),
        py::arg("face_mask") = py::none(), py::arg("tuning") = py::none());
  m.def("detect", &detect, detectDoc.c_str(), py::arg("vertices"), py::arg("faces"), py::kw_only(),
        py::arg("progress") = py::none(), py::arg("tuning") = py::none());
  m.def("mesh_distance", &meshDistance, distanceDoc.c_str(), py::arg("a_vertices"),
        py::arg("a_faces"), py::arg("b_vertices"), py::arg("b_faces"), py::kw_only(),
        py::arg("samples") = 200000, py::arg("seed") = py::none(),
        py::arg("sample_vertices") = true, py::arg("sample_edges") = true,
        py::arg("sampling") = "uniform");

  m.attr("OPTIONS") = optionRecords();
  m.attr("FACE_LABELS") = py::make_tuple("other", "smooth_region", "chamfer", "corner");
}
