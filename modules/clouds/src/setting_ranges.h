#pragma once
// The numeric Settings fields' ranges as one table: validateSettings() checks each, and the
// module's tests hold the table to the ranges clouds.h documents ("// [lo, hi]") and check
// both bounds of each (accepted) and just outside them (refused, naming the field).
#include <span>

#include "clouds/clouds.h"

namespace clouds::detail {

struct SettingRange {
  const char* field;  // as clouds.h names it (and the error message)
  double lo;          // inclusive bounds, as the field's own type holds them
  double hi;
  double (*get)(const Settings&);
  void (*set)(Settings&, double);
  bool integer;  // an unsigned integer field
};

std::span<const SettingRange> settingRanges();

}  // namespace clouds::detail
