#pragma once
// The observation table of the lemma property tests: for every statement of the paper, its
// constant, the tightest value observed over all instances, the margin to the bound and
// the number of instances that contributed. Printed at the end of test_lemmas and written
// to lemmas_table.md in the build directory (proofs/README.md's "observed" column).

#include <cmath>
#include <cstdio>
#include <fstream>
#include <ostream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace rstruct::lemmas {

/// Whether the worst value is the largest (bound is an upper bound) or the smallest;
/// `count` rows record 0 (holds) or 1 (fails) per item and print only the count.
enum class Direction { at_most, at_least, count };

struct Observation {
  Observation(std::string statement_text, std::string constant_text, double bound_value,
              Direction dir)
      : statement(std::move(statement_text)),
        constant(std::move(constant_text)),
        bound(bound_value),
        direction(dir) {}

  std::string statement;  ///< e.g. "L4.2 dist(p,F)/R_p"
  std::string constant;   ///< the paper's bound as text, e.g. "> 0.9807"
  double bound = 0;       ///< the same as a number (for the margin)
  Direction direction = Direction::at_most;
  double worst = NAN;      ///< the tightest value observed (NaN: nothing measured)
  long long measured = 0;  ///< how many values were measured
  long long failures = 0;  ///< how many violated the bound
  int instances = 0;       ///< instances that contributed at least one value
  std::string note;        ///< caveats, counts, errata
  bool asserted = true;    ///< false: the row is reported, its bound is not a claim checked
  int last_instance = -1;

  void add(double value, int instance) {
    ++measured;
    if (instance != last_instance) {
      ++instances;
      last_instance = instance;
    }
    const bool at_least = direction == Direction::at_least;
    const bool worse = std::isnan(worst) || (at_least ? value < worst : value > worst);
    if (worse) worst = value;
    const bool ok = at_least ? value >= bound : value <= bound;
    if (!ok) ++failures;
  }
  /// Margin to the bound: positive when the worst value satisfies it.
  double margin() const { return direction == Direction::at_least ? worst - bound : bound - worst; }
};

inline std::string format_value(double v) {
  if (std::isnan(v)) return "—";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.5g", v);
  return buffer;
}

/// `text` with every '|' escaped, so that it stays inside one Markdown table cell.
inline std::string cell(const std::string& text) {
  std::string out;
  for (const char ch : text) {
    if (ch == '|') out += '\\';
    out += ch;
  }
  return out;
}

/// The table in Markdown.
inline std::string markdown_table(const std::vector<Observation>& rows, const std::string& title) {
  std::ostringstream out;
  out << title << "\n\n";
  out << "| statement | paper's constant | worst observed | margin | failing / measured | "
         "instances | note |\n";
  out << "| --- | --- | --- | --- | --- | --- | --- |\n";
  for (const Observation& o : rows) {
    out << "| " << cell(o.statement) << " | " << cell(o.constant) << " | ";
    if (o.direction == Direction::count) {
      out << o.failures << " failing | — | ";
    } else {
      out << format_value(o.worst) << " | " << format_value(o.margin()) << " | ";
    }
    out << o.failures << " / " << o.measured << " | " << o.instances << " | " << o.note << " |\n";
  }
  return out.str();
}

}  // namespace rstruct::lemmas
