(** The value of every pattern at a point of pattern space (pattern.cpp), before the frequency,
    phase and wave of §17.1 are applied. *)

(** What a few patterns need to know about the surface: aoi and slope. (Slope's [point_at] also
    uses the intersection point in POV-Ray; the pattern-space point stands for it here.) *)
type hit = {
  normal : Vec.t;
      (** the surface normal at the point, world space, unit length, turned to face the ray and not
          perturbed (POV-Ray's PNormal: aoi is 1 where the ray meets the surface head on) *)
  dir : Vec.t;  (** the ray's direction, unit length *)
  uv : Vec.t;
      (** the hit's UV coordinates (u, v, 0) (the shape's UVCoord, {!Shape.uv}), which uv-mapped
          pigments and normals use instead of the point; zero where the surface has none of
          them (the tracer computes them only for a surface that uses them) *)
}

val no_hit : hit
(** [no_hit] is the hit given where there is no surface (a sky_sphere): normal <0,1,0>, dir
    <0,0,1>, uv zero. A hit [{ no_hit with uv }] is still no surface for aoi and slope (a shadow
    ray's crossing of a uv-mapped surface). *)

val checker : Vec.t -> float
(** [checker q] is 0 or 1: the parity of [floor(c + 1e-10)] summed over the three coordinates (§17.4). *)

val gradient : Vec.t -> Vec.t -> float
(** [gradient v q] is [q·v], reduced by [fmod 1] only when above 1 (§17.5); [v] is unit length. *)

val hexagon : Vec.t -> float
(** [hexagon q] is 0, 1 or 2: the hexagonal cell of [q] in the XZ plane (§17.6). *)

val brick : Vec.t -> float -> Vec.t -> float
(** [brick size mortar q] is 0 in the mortar and 1 in a brick (§17.7); [mortar] is the stored width. *)

val value : Scene.pattern -> Scene.warp list -> int -> hit -> Vec.t -> float
(** [value pat warps gen hit q] is the raw value of [pat] at the already warped point [q], with
    noise generator [gen] (1, 2 or 3); [warps] is the pattern's warp list, which marble, wood,
    agate and spiral read their classic turbulence from (POV-Ray's Evaluate_TPat switch). Waves
    and ripples take frequency 1 and phase 0 here: see [value_with]. [hit] is [no_hit] where
    there is no surface, and aoi and slope are then 0, as POV-Ray's are without an intersection.
    Raises [Invalid_argument] for [Facets] and [Average], which have no value in POV-Ray. *)

val value_with : frequency:float -> phase:float -> Scene.pattern -> Scene.warp list -> int -> hit -> Vec.t -> float
(** [value_with ~frequency ~phase pat warps gen hit q] is [value pat warps gen hit q] for a
    pattern whose [frequency] and [phase] are those given: waves and ripples use them inside their
    value (as POV-Ray's waves_pattern and ripples_pattern do), before the wrap of §17.1 uses them
    again; every other pattern ignores them. *)
