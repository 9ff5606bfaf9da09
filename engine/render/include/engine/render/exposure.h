#pragma once
// Camera exposure in photographic units, for the renderer's physical light (kcd/m^2 and klx,
// scene_components.h). EV100 is the exposure value at ISO 100: a radiance of
// 1.2 * 2^EV100 cd/m^2 reaches the display's white before the tonemap curve (saturation-based
// sensitivity, Lagarde & de Rousiers 2014, "Moving Frostbite to PBR"), so the tonemap's linear
// multiplier for kcd/m^2 is 1000 / (1.2 * 2^EV100).
//
// Auto-exposure meters as an incident-light meter held at the camera, facing up: it reads the
// illuminance the sun (through the air) and the sky put on a horizontal surface and sets
// EV100 = log2(E * 100 / C) with the meter calibration C = 250 lx s (ISO 2720), plus the
// compensation. Noon sunlight (about 100 klx) meters EV100 15, the photographers' "sunny 16".
// With a CoveredSkyLight (an effect's cover over the sky) the meter reads the covered sky and
// the sun through the cover at the camera: under an overcast it reads the overcast, and in the
// cover's shadow the shade; without one, the clear sky and the sun through the air alone.
// Below daylight the meter is trusted less and less (dimLightCompensationEv): an incident
// reading of a twilight sky alone would expose it to near white, where the eye (and a
// photographer) sees dusk as dusk. The result adapts towards the metered value exponentially,
// with a time constant, and is clamped, so night stays dark instead of being exposed to grey.
#include <glm/glm.hpp>

namespace engine::render {

struct SkyLight;
struct CoveredSkyLight;

// Context singleton: the exposure the tonemap applies.
struct Exposure {
  enum class Mode { Auto, Manual };
  Mode mode = Mode::Auto;
  float ev100 = 15.0f;             // Manual: the exposure. Auto: the adapted value (the system's)
  float compensationEv = 0.0f;     // Auto: added to the metered value (+1: twice as bright)
  float adaptationSeconds = 0.5f;  // Auto: time constant of the adaptation, >= 0
  float minEv100 = -2.0f;          // Auto: the metered value is clamped to these
  float maxEv100 = 17.0f;
  bool adapted = false;  // Auto: false until the first metered value, which is taken at once
  // Auto: the last value was metered under a CoveredSkyLight. The cover is measured from
  // completed frames, so it arrives a frame or two after the first: its first reading is taken
  // at once too, and the first frames of a scene are not seen adapting from the clear sky's.
  bool meteredCovered = false;
};

// EV100 an incident-light meter (C = 250) reads under `lux`; lux <= 0 reads as 1e-3 lx.
float ev100FromIlluminance(double lux);
// The exposure compensation (stops of brightness, +1 twice as bright) for a metered `ev100`
// in dim light: 0 in daylight (EV100 >= 10, the sun up
// by a few degrees), falling linearly to -3 stops at EV100 0 (deep twilight) and staying there.
float dimLightCompensationEv(float meteredEv100);
// The linear multiplier from kcd/m^2 to the tonemap's input at `ev100`.
float exposureScale(float ev100);
// Illuminance (klx) on a horizontal surface: the sun's (`sunKilolux` RGB, `sunDirectionY` the
// sine of its elevation) plus the sky's, from its cosine-weighted mean radiance estimated as
// 0.8 zenith + 0.2 horizon (exact for a sky mixed by sqrt(sin(elevation)) between the two);
// the luminance of the RGB sum.
double horizontalIlluminanceKilolux(const glm::vec3& sunKilolux, double sunDirectionY,
                                    const SkyLight& sky);
// The same at `altitudeMetres` under a covered sky: below the cover the sun is centre-weighted,
// times the mean of the cover's sunAtCamera and sunAround (a meter in the cover's shadow, with the
// land in view sunlit, reads half way: the camera's spot alone would expose the view for the
// shade and wash out all it sees in the sun), and the sky is its measured irradianceOverPi;
// both blend linearly by altitude into sunAtCamera alone and `clear`'s sky at clearAboveMetres
// and above (what a camera above the cover sees is lit as it is). `covered` null: the clear
// sky's.
double horizontalIlluminanceKilolux(const glm::vec3& sunKilolux, double sunDirectionY,
                                    const SkyLight& clear, const CoveredSkyLight* covered,
                                    double altitudeMetres);
// `current` moved towards `target` over `dtSeconds` with time constant `tauSeconds`.
float adaptEv100(float current, float target, double dtSeconds, double tauSeconds);

}  // namespace engine::render
