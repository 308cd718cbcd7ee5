(** Optics of reflection and transmission (docs/povray-rules.md §4, §5, §6): how much a surface reflects
    (Fresnel), how an interior's fade dims light, and which interiors a ray is in. *)

val fade : Compiled.obj -> float -> Rgb.t -> Rgb.t
(** [fade obj depth c] is [c] after [depth] through [obj]'s interior (§4, §6.3): exponential above
    fade_power 1000, else fade_colour + (1 − fade_colour)/(1 + (depth/fade_distance)^fade_power),
    in single precision. *)

val fades : Compiled.obj -> bool
(** [fades obj] is whether [obj]'s interior fades light: |fade_distance| > EPSILON. *)

val remove : int -> int list -> int list
(** [remove id l] is [l] without the first [id]: a ray leaving that interior. *)

val reflectivity : Compiled.t -> Compiled.surface -> Compiled.obj -> int list -> float -> Rgb.t
(** [reflectivity sc s obj interiors ci] is the reflection colour at the cosine of incidence [ci]
    (§5.2): the falloff blend of reflection min and max, or with [fresnel] the Fresnel term of the
    ratio of the indices of refraction seen from the ray's interiors. *)

val conserved : Compiled.surface -> Rgb.t -> Rgb.t
(** [conserved s refl] is the surface's transmitted filter colour, reduced by what is reflected
    when it conserves energy (§5.4). *)

val bent_reflection : Vec.t -> Vec.t -> Vec.t -> Vec.t
(** [bent_reflection d n raw] is the reflected direction of the ray [d] off a normal [n] bent by a
    normal pattern (§5.3, trace.cpp's ComputeReflection): the mirror direction, unless it points
    below the surface by the shape's own normal [raw]; then the mirror direction off [raw] when it
    is below [n]'s plane too, else the mirror direction reflected again in [raw]'s plane; made unit. *)
