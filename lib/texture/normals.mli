(** Perturbed normals (normal.cpp): a normal pattern bends the surface normal at a point. *)

val perturb : int -> Scene.normal -> Vec.t -> Patterns.hit -> Vec.t -> Vec.t
(** [perturb gen nm p hit n] is the normal [n] (unit, world space) at the world point [p] bent by
    [nm], as POV-Ray's Perturb_Normal: the pattern's own normal function where it has one
    (bumps, dents, ripples, waves, wrinkles, quilted, facets, average), else the finite-difference
    slope of its value (with slope_map / normal_map), scaled by the bump size, through the
    normal's warps; [gen] is the scene's noise generator, used where the normal has none. The
    result is normalised, as POV-Ray does before shading (unless [no_bump_scale] says otherwise). *)
