// The module's shader contracts reach its host through the module's target alone: these
// headers compile as C++ with what linking the module brings.
#include "fxcontracts/cloud_shadow.h"
#include "fxcontracts/god_rays.h"
#include "fxcontracts/lightning_light.h"

// A use of each, so that a header that declares nothing usable fails to build.
static_assert(fxcontracts::shader::kCloudShadowMaxCascades == 4);
