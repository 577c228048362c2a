// FreeFEM glue of the files, the results folders, the CSV rows, the VTU frames, JSON and the
// clocks (plugin/core: files, output, json, mesh_check, contact_history). The functions are listed
// in load.cpp.
#include "glue/glue.hpp"

#include <filesystem>

#include "core/contact_history.hpp"
#include "core/files.hpp"
#include "core/json.hpp"
#include "core/mesh_check.hpp"
#include "core/output.hpp"
#include "core/process.hpp"

namespace sma_glue {
namespace {

// FreeFEM's time() has a resolution of one second and clock() counts CPU time; timings of the
// scenes are wall-clock seconds from a monotonic clock.
double WallSeconds() {
  using namespace std::chrono;
  return duration<double>(steady_clock::now().time_since_epoch()).count();
}

string* RealDigits(Stack stack, double const& x, long const& digits) {
  std::ostringstream text;
  text.precision(std::clamp(digits, 1L, 17L));
  text << x;
  return NewString(stack, text.str());
}

string* FileMakeDirectory(Stack stack, string* const& path) {
  return NewString(stack, sma::files::make_directory(*path));
}
string* FileRename(Stack stack, string* const& from, string* const& to) {
  return NewString(stack, sma::files::rename_file(*from, *to));
}
string* FileRemoveMatching(Stack stack, string* const& dir, string* const& patterns) {
  return NewString(stack, sma::files::remove_matching(*dir, *patterns));
}
long FileKind(string* const& path) { return sma::files::kind(*path); }
string* FileAbsolute(Stack stack, string* const& path) { return NewString(stack, sma::files::absolute(*path)); }
long FileEndsWith(string* const& path, string* const& tail) { return sma::files::ends_with(*path, *tail); }
string* FileChecksum(Stack stack, string* const& path, double const& length) {
  return NewString(stack, sma::files::checksum(*path, std::llround(length)));
}
string* FileSeal(Stack stack, string* const& path) { return NewString(stack, sma::files::seal(*path)); }
string* FileSealError(Stack stack, string* const& path) { return NewString(stack, sma::files::seal_error(*path)); }
string* StreamReadNumbers(Stack stack, std::istream* const& in, KN<double>* const& values, string* const& name,
                          long const& integer) {
  return NewString(stack, sma::files::read_numbers(*in, values->N() ? &(*values)[0] : nullptr,
                                                   (std::size_t)values->N(), integer != 0, *name));
}
string* FileTruncate(Stack stack, string* const& path, double const& length) {
  return NewString(stack, sma::files::truncate_file(*path, std::llround(length)));
}

// The folders this process locked: their locks are removed at exit, however the script ends
// (normal end, Fail's exit(1), FreeFEM's own error exit). A killed process leaves a lock that the
// next run finds stale (its process is gone) and takes.
std::vector<std::string>& ClaimedFolders() {
  static std::vector<std::string> folders;
  return folders;
}
void ReleaseClaimedFolders() {
  for (const auto& dir : ClaimedFolders()) {
    const std::string note = sma::files::release_results_noted(dir, (long)getpid());
    if (!note.empty()) std::fprintf(stderr, "%s\n", note.c_str());
  }
}
// The entries this process has recorded in a manifest (files.hpp record_result).
sma::files::RecordedResults& RecordedResults() {
  static sma::files::RecordedResults known;
  return known;
}
string* Claim(Stack stack, const std::string& dir, const std::string& scene, bool resume, const std::string& patterns) {
  std::string error = sma::files::claim_results(dir, scene, (long)getpid(), resume, patterns);
  RecordedResults().clear();  // a fresh claim started a new manifest
  if (error.empty()) {
    if (ClaimedFolders().empty()) std::atexit(ReleaseClaimedFolders);
    ClaimedFolders().push_back(dir);
  }
  return NewString(stack, error);
}
string* ResultsClaim(Stack stack, string* const& dir, string* const& scene) {
  return Claim(stack, *dir, *scene, false, "");
}
string* ResultsClaimResumed(Stack stack, string* const& dir, string* const& scene, string* const& patterns) {
  return Claim(stack, *dir, *scene, true, *patterns);
}
string* ResultsRecord(Stack stack, string* const& path) {
  return NewString(stack, sma::files::record_result(*path, RecordedResults()));
}

// Called on every published file: the folder's record (summary.json) completes its run.
string* ResultsPublished(Stack stack, string* const& path) {
  for (const auto& dir : ClaimedFolders())
    if (sma::files::is_record_of(*path, dir)) return NewString(stack, sma::files::complete_results(dir, (long)getpid()));
  return NewString(stack, "");
}

long ResultsRelease(string* const& dir) {
  sma::files::release_results(*dir, (long)getpid());
  return 0;
}

// FreeFEM never checks its ofstreams: a full disk leaves a short file and no message. Flushing
// and reading the stream's state tells whether every write so far reached the file.
string* StreamWriteError(Stack stack, std::ostream* const& stream) {
  errno = 0;
  stream->flush();
  if (stream->good()) return NewString(stack, "");
  const int saved = errno;
  return NewString(stack, std::string("a write failed (") + (saved ? std::strerror(saved) : "disk full?") + ")");
}

string* JsonFileError(Stack stack, string* const& path) {
  std::ifstream in(*path, std::ios::binary);
  if (!in) return NewString(stack, "cannot read " + *path);
  std::stringstream text;
  text << in.rdbuf();
  const std::string error = sma::json::validate(text.str());
  return NewString(stack, error.empty() ? "" : *path + " is not valid JSON: " + error);
}
string* MeshFileError(Stack stack, string* const& path, double const& min_quality) {
  return NewString(stack, sma::mesh::check_msh(*path, min_quality));
}
// A ParaView VTU file of mesh Th in savevtk's bytes (plugin/core/output.hpp): point fields, a
// vector (2 values per vertex, interleaved: a [P1, P1] function's array) and a scalar (a P1
// function's array), and cell fields, the columns of `cells` (one row per triangle: P0 arrays)
// named by the words of cellNames. Returns 0, or -1 when the file could not be written.
long VtuWrite(string* const& path, pmesh const& Th, string* const& vectorName, KN<double>* const& vector,
              string* const& scalarName, KN<double>* const& scalar, string* const& cellNames,
              KNM<double>* const& cells) {
  return guarded("VtuWrite", [&] {
    const Mesh& mesh = *Th;
    const long nv = mesh.nv, nt = mesh.nt;
    std::istringstream words(*cellNames);
    std::vector<std::string> names{std::istream_iterator<std::string>(words), std::istream_iterator<std::string>()};
    if (vector->N() != 2 * nv || scalar->N() != nv)
      throw std::invalid_argument("the point fields need 2 and 1 values per vertex (" + std::to_string(nv) + " vertices)");
    if (cells->N() != nt || cells->M() != (long)names.size())
      throw std::invalid_argument("the cell fields need one row per triangle (" + std::to_string(nt)
                                  + ") and one column per name of '" + *cellNames + "'");
    sma::output::VtuMesh m;
    m.x.resize(nv); m.y.resize(nv); m.triangles.resize(3 * nt); m.labels.resize(nt);
    for (long v = 0; v < nv; ++v) { m.x[v] = mesh(v).x; m.y[v] = mesh(v).y; }
    for (long t = 0; t < nt; ++t) {
      for (int k = 0; k < 3; ++k) m.triangles[3 * t + k] = mesh(t, k);
      m.labels[t] = mesh[t].lab;
    }
    std::vector<sma::output::VtuField> cellFields, pointFields;
    for (std::size_t j = 0; j < names.size(); ++j) {
      sma::output::VtuField f{names[j], 1, std::vector<double>(nt)};
      for (long t = 0; t < nt; ++t) f.values[t] = (*cells)(t, (long)j);
      cellFields.push_back(f);
    }
    pointFields.push_back({*vectorName, 2, std::vector<double>(&(*vector)[0], &(*vector)[0] + 2 * nv)});
    pointFields.push_back({*scalarName, 1, std::vector<double>(&(*scalar)[0], &(*scalar)[0] + nv)});
    // The mesh's part once a run (and again when the mesh changes): the frames share it.
    static sma::output::VtuMeshText meshText;
    std::string text = meshText.of(m);
    sma::output::vtu_fields_part(m, cellFields, pointFields, text);
    std::FILE* file = std::fopen(path->c_str(), "wb");
    if (!file) return -1L;
    const bool written = std::fwrite(text.data(), 1, text.size(), file) == text.size();
    return (std::fclose(file) == 0 && written) ? 0L : -1L;
  });
}

// The in-plane stresses of the P1 displacement u per triangle (plugin/core/output.hpp
// plane_stress_p1): Dx, Dy the P0 <- P1 interpolation matrices of the derivatives
// (interpolate(Ph, Wh, op = 1) and op = 2: the coefficients FreeFEM's element computes), lame =
// [lambda, mu]; sxx, syy, sxy receive one value per triangle.
long PlaneStressAtCentroids(pmesh const& Th, Matrice_Creuse<double>* const& Dx, Matrice_Creuse<double>* const& Dy,
                            KN<double>* const& u, KN<double>* const& lame, KN<double>* const& sxx,
                            KN<double>* const& syy, KN<double>* const& sxy) {
  return guarded("PlaneStressAtCentroids", [&] {
    const Mesh& mesh = *Th;
    const long nv = mesh.nv, nt = mesh.nt;
    if (u->N() != 2 * nv) throw std::invalid_argument("u needs 2 values per vertex");
    if (lame->N() != 2) throw std::invalid_argument("lame must be [lambda, mu]");
    std::vector<int> triangles(3 * nt);
    for (long t = 0; t < nt; ++t)
      for (int k = 0; k < 3; ++k) triangles[3 * t + k] = mesh(t, k);
    // the matrices' entries read in place (not converted to Eigen's matrices at every frame)
    auto gradients = [&](Matrice_Creuse<double>* D) {
      HashMatrix<int, double>* A = D->pHM();
      if (!A || A->n != nt || A->m != nv || A->half)
        throw std::invalid_argument("Dx and Dy must be triangles x vertices (interpolate(Ph, Wh, op = 1), op = 2)");
      std::vector<int> expanded;
      return sma::output::centroid_gradients(triangles, EntryRows(*A, expanded), A->j, A->aij, A->nnz,
                                             A->fortran ? 1 : 0);
    };
    const std::vector<double> gx = gradients(Dx), gy = gradients(Dy);
    sxx->resize(nt); syy->resize(nt); sxy->resize(nt);
    sma::output::plane_stress_p1(triangles, gx, gy, &(*u)[0], (*lame)[0], (*lame)[1], &(*sxx)[0], &(*syy)[0],
                                 &(*sxy)[0]);
    return 0L;
  });
}


// CSV rows at the stream's precision in the characters `f << x` writes (plugin/core/output.hpp):
// a row's values comma-separated (no line end), or every row of a table, each ended by a line end.
int CsvPrecision(std::ostream* f) {
  if ((f->flags() & std::ios::floatfield) != std::ios::fmtflags(0) || (f->flags() & std::ios::showpoint))
    throw std::invalid_argument("the stream must print reals in the default format (no fixed, scientific or showpoint)");
  return static_cast<int>(f->precision());
}
// The rows' formatters by stream (a row's text does not depend on which one formats it: each
// checks its kept texts against the values' bits and the precision), one per stream a run writes
// rows to, so that each keeps the columns of its own file's last row.
sma::output::CsvRowFormatter& RowFormatter(const std::ostream* f) {
  static std::unordered_map<const std::ostream*, sma::output::CsvRowFormatter> formatters;
  return formatters[f];
}
long CsvWriteRow(std::ostream* const& f, KN<double>* const& values) {
  return guarded("CsvWriteRow", [&] {
    const std::string row = RowFormatter(f).row(values->N() ? &(*values)[0] : nullptr, values->N(), CsvPrecision(f));
    f->write(row.data(), (std::streamsize)row.size());
    return 0L;
  });
}
long CsvWriteRows(std::ostream* const& f, KNM<double>* const& table) {
  return guarded("CsvWriteRows", [&] {
    const int precision = CsvPrecision(f);
    std::vector<double> row(table->M());
    std::string text;
    sma::output::CsvRowFormatter formatter;  // (a column's repeated values formatted once)
    for (long i = 0; i < table->N(); ++i) {
      for (long j = 0; j < table->M(); ++j) row[j] = (*table)(i, j);
      text += formatter.row(row.data(), row.size(), precision);
      text += '\n';
    }
    f->write(text.data(), (std::streamsize)text.size());
    return 0L;
  });
}

long ProbeRowWrite(std::ostream* const& f, KN<double>* const& head, KN<double>* const& at, KN<double>* const& T,
                   KN<double>* const& pressure, KN<double>* const& u, KNM<double>* const& contact,
                   KN<double>* const& pipeNormalMotion) {
  return guarded("ProbeRowWrite", [&] {
    if (head->N() != 3) throw std::invalid_argument("the row's head must be [step, time, pipeElastic]");
    if (at->N() % 2 != 0) throw std::invalid_argument("the probe points must be pairs [contact node, vertex]");
    const long count = at->N() / 2, m = contact->N();
    const bool elastic = (*head)[2] != 0;
    if (contact->M() < 4) throw std::invalid_argument("contactTable must have the columns [vertex, nx, ny, gap, ...]");
    if (pressure->N() != m || (elastic && pipeNormalMotion->N() != m))
      throw std::invalid_argument("pressure (and the pipe's motion) need one value per contact node");
    std::vector<sma::contact_history::ProbePoint> points(count);
    for (long p = 0; p < count; ++p) {
      const long node = lrint((*at)[2 * p]), vertex = lrint((*at)[2 * p + 1]);
      if (node < 0 || node >= m || vertex < 0 || vertex >= T->N() || 2 * vertex + 1 >= u->N())
        throw std::invalid_argument("probe point " + std::to_string(p) + ": no contact node " + std::to_string(node)
                                    + " or vertex " + std::to_string(vertex));
      points[p] = {node, vertex, (*contact)(node, 1L), (*contact)(node, 2L), (*contact)(node, 3L)};
    }
    std::vector<double> row(2 + 3 * count);
    row[0] = (*head)[0];
    row[1] = (*head)[1];
    if (count > 0)
      sma::contact_history::probe_columns(points.data(), count, &(*T)[0], &(*pressure)[0], &(*u)[0],
                                          elastic ? &(*pipeNormalMotion)[0] : nullptr, &row[2]);
    std::string text = RowFormatter(f).row(row.data(), row.size(), CsvPrecision(f));
    text += '\n';
    f->write(text.data(), (std::streamsize)text.size());
    return 0L;
  });
}

string* JsonQuote(Stack stack, string* const& text) { return NewString(stack, sma::json::quote(*text)); }
string* ShellQuote(Stack stack, string* const& text) { return NewString(stack, sma::files::shell_quote(*text)); }
long RunCommand(string* const& command) { return sma::process::run_shell(*command); }
long StopBySignal(long const& sig) {
  std::cout.flush();
  std::cerr.flush();
  sma::process::stop_by_signal((int)sig);
  std::exit(128 + (int)sig);  // (not reached when the signal ends the process, as it does)
}
// The scratch folders this process made: removed at exit with what they hold, however the script
// ends (a refusal's exit(1) after the folder was made left it in /tmp), as the claimed folders' locks.
std::vector<std::string>& TemporaryFolders() {
  static std::vector<std::string> folders;
  return folders;
}
void RemoveTemporaryFolders() {
  for (const auto& dir : TemporaryFolders()) {
    std::error_code ignored;  // (already removed by the script: nothing to do)
    std::filesystem::remove_all(dir, ignored);
  }
}
string* TemporaryDirectory(Stack stack, string* const& prefix) {
  std::string dir = sma::process::temporary_directory(*prefix);
  if (!dir.empty()) {
    if (TemporaryFolders().empty()) std::atexit(RemoveTemporaryFolders);
    TemporaryFolders().push_back(dir);
  }
  return NewString(stack, dir);
}

}  // namespace

void AddOutputFunctions() {
  typedef KN<double>* A;
  typedef string* S;
  Global.Add("WallSeconds", "(", new OneOperator0<double>(WallSeconds));
  Global.Add("FileMakeDirectory", "(", new OneOperator1s_<S, S>(FileMakeDirectory));
  Global.Add("FileRename", "(", new OneOperator2s_<S, S, S>(FileRename));
  Global.Add("RealDigits", "(", new OneOperator2s_<S, double, long>(RealDigits));
  Global.Add("FileRemoveMatching", "(", new OneOperator2s_<S, S, S>(FileRemoveMatching));
  Global.Add("FileKind", "(", new OneOperator1_<long, S>(FileKind));
  Global.Add("FileAbsolute", "(", new OneOperator1s_<S, S>(FileAbsolute));
  Global.Add("FileEndsWith", "(", new OneOperator2_<long, S, S>(FileEndsWith));
  Global.Add("FileTruncate", "(", new OneOperator2s_<S, S, double>(FileTruncate));
  Global.Add("FileChecksum", "(", new OneOperator2s_<S, S, double>(FileChecksum));
  Global.Add("FileSeal", "(", new OneOperator1s_<S, S>(FileSeal));
  Global.Add("FileSealError", "(", new OneOperator1s_<S, S>(FileSealError));
  Global.Add("StreamReadNumbers", "(", new OneOperator4s_<S, std::istream*, A, S, long>(StreamReadNumbers));
  Global.Add("ResultsClaim", "(", new OneOperator2s_<S, S, S>(ResultsClaim));
  Global.Add("ResultsClaimResumed", "(", new OneOperator3s_<S, S, S, S>(ResultsClaimResumed));
  Global.Add("ResultsRecord", "(", new OneOperator1s_<S, S>(ResultsRecord));
  Global.Add("ResultsRelease", "(", new OneOperator1_<long, S>(ResultsRelease));
  Global.Add("ResultsPublished", "(", new OneOperator1s_<S, S>(ResultsPublished));
  Global.Add("StreamWriteError", "(", new OneOperator1s_<S, std::ostream*>(StreamWriteError));
  Global.Add("JsonFileError", "(", new OneOperator1s_<S, S>(JsonFileError));
  Global.Add("VtuWrite", "(", new OneOperator8_<long, S, pmesh, S, A, S, A, S, KNM<double>*>(VtuWrite));
  Global.Add("PlaneStressAtCentroids", "(",
             new OneOperator8_<long, pmesh, Matrice_Creuse<double>*, Matrice_Creuse<double>*, A, A, A, A, A>(
                 PlaneStressAtCentroids));
  Global.Add("CsvWriteRow", "(", new OneOperator2_<long, std::ostream*, A>(CsvWriteRow));
  Global.Add("CsvWriteRows", "(", new OneOperator2_<long, std::ostream*, KNM<double>*>(CsvWriteRows));
  Global.Add("ProbeRowWrite", "(", new OneOperator8_<long, std::ostream*, A, A, A, A, A, KNM<double>*, A>(ProbeRowWrite));
  Global.Add("JsonQuote", "(", new OneOperator1s_<S, S>(JsonQuote));
  Global.Add("MeshFileError", "(", new OneOperator2s_<S, S, double>(MeshFileError));
  Global.Add("ShellQuote", "(", new OneOperator1s_<S, S>(ShellQuote));
  Global.Add("RunCommand", "(", new OneOperator1_<long, S>(RunCommand));
  Global.Add("StopBySignal", "(", new OneOperator1_<long, long>(StopBySignal));
  Global.Add("TemporaryDirectory", "(", new OneOperator1s_<S, S>(TemporaryDirectory));
}

}  // namespace sma_glue
