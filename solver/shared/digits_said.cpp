#include "solver/shared/digits_said.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <string>

#include "solver/numeric/condition.hpp"

namespace frustum {

namespace {

constexpr Phrase kKeepsNoDigit{"{0} keeps no correct digit", "{0} では正しい桁が残らない",
                               "в {0} не остаётся ни одной верной цифры"};
constexpr Phrase kKeepsAbout{"{0} keeps about {1} of its {2} digits",
                             "{0} では {2} 桁のうち約 {1} 桁が残る",
                             "в {0} остаётся около {1} из {2} цифр"};
constexpr Phrase kKappaAbout{"κ ≈ {0}: {1}; the exact value shown is unaffected",
                             "κ ≈ {0}: {1}. 示した厳密値には影響しない",
                             "κ ≈ {0}: {1}; показанное точное значение от этого не зависит"};
constexpr Phrase kKappaInfinite{"κ = ∞: {0}; the exact value shown is unaffected",
                                "κ = ∞: {0}. 示した厳密値には影響しない",
                                "κ = ∞: {0}; показанное точное значение от этого не зависит"};
constexpr Phrase kEveryBackendKeeps{
    "float keeps about {0} of its {1} digits, double keeps about {2} of its {3} digits, "
    "long-double keeps about {4} of its {5} digits",
    "float では {1} 桁中およそ {0} 桁, double では {3} 桁中およそ {2} 桁, long double では {5} "
    "桁中およそ {4} 桁が残る",
    "во float остаётся около {0} из {1} цифр, в double — около {2} из {3}, в long double — около "
    "{4} из {5}"};
constexpr Phrase kFloatKeepsNoDigit{
    "float keeps no correct digit, double keeps about {0} of its {1} digits, long-double keeps "
    "about {2} of its {3} digits",
    "float では正しい桁は残らず, double では {1} 桁中およそ {0} 桁, long double では {3} "
    "桁中およそ {2} 桁が残る",
    "во float не остаётся ни одной верной цифры, в double — около {0} из {1} цифр, в long double "
    "— около {2} из {3}"};
constexpr Phrase kOnlyLongDoubleKeeps{
    "float keeps no correct digit, double keeps no correct digit, long-double keeps about {0} of "
    "its {1} digits",
    "float では正しい桁は残らず, double でも残らず, long double では {1} 桁中およそ {0} 桁が残る",
    "во float не остаётся ни одной верной цифры, в double — тоже, в long double — около {0} из "
    "{1} цифр"};
constexpr Phrase kNoBackendKeeps{
    "float keeps no correct digit, double keeps no correct digit, long-double keeps no correct "
    "digit",
    "float でも double でも long double でも正しい桁は残らない",
    "ни во float, ни в double, ни в long double не остаётся ни одной верной цифры"};

std::string one_decimal(double d) { return fmt::format("{:.1f}", d); }

}  // namespace

Said backend_digits(double kappa, Precision p) {
  const double d = trusted_digits(kappa, p);
  if (d < 0.5) return say(kKeepsNoDigit, to_string(p));
  return say(kKeepsAbout, to_string(p), one_decimal(d), one_decimal(decimal_digits(p)));
}

Said digits_said(double kappa, double kappa_float, double kappa_double, double kappa_long_double) {
  constexpr std::array<Precision, 3> kBackends = {Precision::Float, Precision::Double,
                                                  Precision::LongDouble};
  const std::array<double, 3> kappas = {kappa_float, kappa_double, kappa_long_double};
  std::array<bool, 3> none{};
  std::array<std::string, 3> kept, of;
  for (std::size_t i = 0; i < kBackends.size(); ++i) {
    const double d = trusted_digits(kappas[i], kBackends[i]);
    none[i] = d < 0.5;
    kept[i] = one_decimal(d);
    of[i] = one_decimal(decimal_digits(kBackends[i]));
  }
  Said backends;
  if (none == std::array{false, false, false}) {
    backends = say(kEveryBackendKeeps, kept[0], of[0], kept[1], of[1], kept[2], of[2]);
  } else if (none == std::array{true, false, false}) {
    backends = say(kFloatKeepsNoDigit, kept[1], of[1], kept[2], of[2]);
  } else if (none == std::array{true, true, false}) {
    backends = say(kOnlyLongDoubleKeeps, kept[2], of[2]);
  } else if (none == std::array{true, true, true}) {
    backends = say(kNoBackendKeeps);
  } else {  // a longer backend losing digits a shorter one keeps: each said on its own
    for (std::size_t i = 0; i < kBackends.size(); ++i) {
      if (i > 0) backends.append(Said::verbatim(", "));
      backends.append(backend_digits(kappas[i], kBackends[i]));
    }
  }
  return std::isfinite(kappa) ? say(kKappaAbout, fmt::format("{:.1e}", kappa), backends)
                              : say(kKappaInfinite, backends);
}

}  // namespace frustum
