(** What light meets along a ray between where the ray left and the surface it meets: today an
    interior's fade (docs/povray-rules.md §4, §6.3). Fog and media will act here too. *)

val through : Ray.kind -> Compiled.obj -> int list -> float -> Rgb.t -> Rgb.t
(** [through kind obj interiors depth c] is the colour [c] brought back along the last [depth] of
    a ray of [kind], inside [interiors], that met the surface of [obj]: faded by [obj]'s interior
    ({!Optics.fade}) when the ray ran inside it ([interiors] holds it) and its fade_distance is
    set (|fade_distance| > EPSILON); for a shadow ray only with fade_power > 0 too (§4), for the
    others with any fade_power (§6.3, §13.11). *)
