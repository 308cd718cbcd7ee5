(** Local illumination (docs/povray-rules.md §3.3, §3.4, §18.2, §18.3): what the light sources add to a
    surface point, each through its shadow feeler — diffuse (N·L, brilliance), Phong and specular
    highlights (metallic tint) — and how a light's colour is attenuated on the way. *)

type memo
(** The light colour cache of one shaded point (trace.cpp's lightColorCache): each light's colour
    after its shadow feeler, once it has been tested. *)

val memo : Compiled.t -> memo
(** [memo sc] is an empty cache for the lights of [sc]. *)

val no_memo : memo
(** [no_memo] is no cache at all: each test sends its feeler. *)

val add_lights :
  Context.t ->
  memo:memo ->
  level:int ->
  di:bool ->
  Compiled.surface ->
  Vec.t ->
  Vec.t ->
  Vec.t ->
  float ->
  Vec.t ->
  int list ->
  Rgb.t ->
  Rgb.t
(** [add_lights ctx ~level ~di s p n ng e d interiors acc] is [acc] plus every light's diffuse,
    phong and specular terms at the point [p] with the normal [n] (turned toward the ray), seen
    along [d] by a ray at trace [level] inside [interiors], summed in single precision the way
    POV-Ray sums them: per light first, then into the colour. [di]: the object is
    double_illuminate (§16.6, lit from behind too); [ng] and [e] place the shadow feelers' origins
    in the robust mode. With a [memo] (not {!no_memo}), a light's shadow feeler is sent only the first time the
    light is tested at this point (the layers and entries of one texture share it); later tests
    take its colour from [memo]. *)

val iridescence : Compiled.t -> Compiled.surface -> Vec.t -> Vec.t -> Vec.t -> Vec.t -> Rgb.t -> Rgb.t
(** [iridescence sc s l d n p c] is [c] tinted by the thin film of [s] (POV-Ray's
    ComputeIridColour): light arriving along [l], seen along [d], at the point [p] with the normal
    [n]; the phase 2π·thickness·(|n·l| + |n·d|) over each of the scene's irid wavelengths, the
    thickness varied by 5 octaves of turbulence when [s] has an irid turbulence. *)

val metallic_factor : float -> float -> Rgb.t -> Rgb.t -> Rgb.t
(** [metallic_factor metallic cos_angle c lc] is [lc] tinted by the surface colour [c] with
    POV-Ray's empirical metallic Fresnel term (§3.3), for highlights and metallic reflection. *)

val cubic_spline : float -> float -> float -> float
(** [cubic_spline lo hi p] is 0 below [lo], 1 from [hi] on, and (3 − 2s)s² with s = (p − lo)/(hi − lo)
    between: the soft edge of spotlights and cylinder lights (§3.4). *)

val attenuation : Compiled.light -> Vec.t -> Vec.t -> float -> float
(** [attenuation light p l dist] is the factor of [light]'s colour at the point [p] whose light ray
    has the unit direction [l] (towards the light) and length [dist] (§3.4, Attenuate_Light): the
    spotlight cone (cos^tightness, the cubic spline between the falloff and radius cosines, 0 behind),
    the cylinder beam, then fade. *)

val parallel_depth : Compiled.light -> Vec.t -> float -> float
(** [parallel_depth light l dist] is the length of a parallel light's ray from a point at distance
    [dist] from its centre in the unit direction [l]: the point's signed distance in front of the
    plane through the centre perpendicular to the light's direction (§18.3). *)
