(** Perturbed normals (normal.cpp): a normal pattern bends the surface normal at a point. *)

type facets_cache
(** The points facets searched last and the hash of their cube, which POV-Ray keeps per render
    thread and reuses for any later cube of the same hash (normal.cpp, Facets_Last_Seed). *)

val facets_cache : unit -> facets_cache
(** [facets_cache ()] is an empty cache, as at the start of a POV-Ray render thread. *)

val reset_facets : facets_cache -> unit
(** [reset_facets c] empties [c]. *)

val perturb : ?facets:facets_cache -> int -> Scene.normal -> Vec.t -> Patterns.hit -> Vec.t -> Vec.t
(** [perturb ?facets gen nm p hit n] is the normal [n] (unit, world space, turned toward the ray) at the
    world point [p] bent by [nm], as POV-Ray's Perturb_Normal: with a normal_map, the entries'
    normals blended by the pattern's value; else the pattern's own normal function where it has
    one (bumps, dents, ripples, waves, wrinkles, quilted, facets, average), else the
    finite-difference slope of its value (through the slope_map if any) scaled by the bump size;
    all in the normal's own space (its warps' transforms). [hit] is the hit the slope and aoi
    patterns see ([hit.normal] the normal before perturbation); [gen] is the scene's noise
    generator, used where the normal names none. The result is the vector POV-Ray leaves as the
    intersection's perturbed normal: unit length unless [no_bump_scale] (see {!layer_normal}).
    facets searches the cube points in [facets] when its hash is the cache's (and updates it), as
    POV-Ray does; without [facets], the points around the point itself. A uv-mapped normal (and a
    uv-mapped entry of a map) is evaluated at [hit.uv] instead of its point, its result normalised. *)

val layer_normal : Scene.normal -> Vec.t -> Vec.t
(** [layer_normal nm v] is the shading normal from the result [v] of [perturb]: [v] itself, or,
    with [no_bump_scale] (not uv-mapped: trace.cpp tests the wrapper's flag), [v] divided by its
    length (trace.cpp normalises it there). *)

val warp_normal : Scene.warp list -> keep_scale:bool -> Vec.t -> Vec.t
(** [warp_normal ws ~keep_scale n] is the world-space normal [n] taken into the space of the warps
    [ws] (their transforms, the head first: POV-Ray's Warp_Normal), normalised before and after
    unless [keep_scale] (no_bump_scale). *)

val unwarp_normal : Scene.warp list -> keep_scale:bool -> Vec.t -> Vec.t
(** [unwarp_normal ws ~keep_scale n] takes [n] back to world space (UnWarp_Normal), the inverse walk
    of {!warp_normal}. *)

val slope_value : Scene.slope_entry array -> float -> float
(** [slope_value map v] is the height a slope_map gives the value [v] (Do_Slope_Map): the Hermite
    cubic through the heights and slopes of the entries around [v], or the entry's height beyond
    the ends and on an entry's value. [map] is not empty. *)

val cycloidal : float -> float
(** [cycloidal v] is POV-Ray's sin(2πv), computed on the fraction of [v] scaled by 50000 and back,
    odd about 0 (texture.cpp). *)

val quilt_cubic : float -> float -> float -> float
(** [quilt_cubic t c0 c1] is the quilted pattern's cubic: the Bézier curve from 0 to 1 with control
    values [c0] and [c1] at [t], over √(3/4) (pattern.cpp). *)
