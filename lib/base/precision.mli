(** POV-Ray's precision rules, defined once: single-precision rounding and the tolerances every
    stage shares (docs/povray-rules.md §2.1, §4, §8.3). *)

val f32 : float -> float
(** [f32 x] is [x] rounded to single precision, as POV-Ray stores colours, bounding boxes and
    mesh vertices (§8.3). *)

val epsilon : float
(** [epsilon] is POV-Ray's EPSILON, 1e-10: the threshold of its "is this zero" tests. *)

val min_isect_depth : float
(** [min_isect_depth] is 1e-4: every ray ignores hits closer than this (§2.1, MIN_ISECT_DEPTH). *)

val shadow_tolerance : float
(** [shadow_tolerance] is 1e-3: shadow hits count only from this depth to the light minus it (§4). *)
