(** What a ray that meets nothing sees (docs/povray-rules.md §8.4, §18.1): the background colour, or the
    sky_sphere's pigments in the ray's direction over it. *)

val colour : Compiled.t -> Vec.t -> Traced.t
(** [colour sc d] is the colour seen along the unit direction [d] past every object: the sky
    sphere's pigments evaluated at [d] taken as a point (brought back through the sky's own
    transform), layered over the background, by the 3.7 rule or, below version 3.70, the legacy
    one; without a sky, the background (with its transmit in a legacy scene). *)
