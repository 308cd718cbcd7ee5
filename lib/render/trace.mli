(** The recursive Whitted tracer (POVRAY-3.7 §2–§7): the colour seen along one ray. *)

type result = { r : float; g : float; b : float; tr : float }
(** A traced colour, in the working colour space, with its transmittance (used only by the
    antialiasing comparison, §9.5). *)

type ctx = {
  scene : Compiled.t;
  stats : Stats.t;
  depth : float array;
  sub : int array;
  stack : float array;
  mstack : float array;
  lim : Limits.t;
  min_depth : float;
  robust : bool;
  shadow_cache : int array;
  slab : float array;
  hits : hits;
  leaf : int array;
}
(** What a trace reads: the compiled scene, the worker's statistics, scratch space (the last
    hit's depth and mesh face, traversal stacks, a box's crossings, a CSG's hits and member hit) and POV-Ray's shadow cache (§4: per light, the
    opaque object that last blocked it), all private to one worker; and the mode's limits: the
    depths shapes accept, the nearest depth any ray accepts (1e-4, §2.1), and whether secondary
    rays leave from points lifted off the surface (robust mode). *)

and hits = { mutable h : float array }
(** Room for the hits of a CSG's members, [hit_width] floats per hit: depth, side or face, the
    member's id, the hit point's x, y, z. It grows when a ray crosses more surfaces. *)


val make_ctx : ?robust:bool -> Compiled.t -> Stats.t -> ctx
(** [make_ctx ?robust scene stats] is a context for one render worker, with an empty shadow cache
    (as at the start of a POV-Ray render thread); [robust] (default false) selects the robust
    mode's limits instead of POV-Ray's. The render loop makes one per block, so the image does not
    depend on which worker renders which blocks. *)

val hit_shape : ctx -> Compiled.shape -> Vec.t -> Vec.t -> float -> float
(** [hit_shape ctx shape o d lo] is the nearest depth along the unit direction [d] at which the ray
    from [o] meets [shape] within the shape's own limits and at least [lo] (§2, §14.5), or
    infinity; for a mesh the face, for a box the side (1–6: X−, X+, Y−, Y+, Z−, Z+), is left in
    [ctx.sub.(0)]. *)

val hit_width : int
(** [hit_width] is the number of floats per hit in [ctx.hits]. *)

val all_hits : ctx -> Compiled.obj -> Vec.t -> Vec.t -> float -> int -> int
(** [all_hits ctx ob o d lo n] appends to [ctx.hits], after its first [n] hits, every crossing at
    depth ≥ [lo] of the primitive or CSG [ob] along the ray that POV-Ray's All_Intersections
    keeps (§16.2), in the order it pushes them; it returns the new number of hits. *)

val normal : Compiled.obj -> int -> Vec.t -> Vec.t
(** [normal obj face p] is the unit normal of [obj] at its surface point [p] ([face]: the mesh face
    or box side hit, else ignored), before it is turned toward the ray (§3.1, §14.6). *)

val black : result
(** [black] is what a ray cut off by max_trace_level or adc_bailout returns. *)

val f32 : float -> float
(** [f32 x] is [x] rounded to single precision, as POV-Ray stores colours (§8.3). *)

val trace : ctx -> level:int -> weight:float -> interiors:int list -> continued:bool -> Vec.t -> Vec.t -> result
(** [trace ctx ~level ~weight ~interiors ~continued origin dir] is the colour seen from [origin]
    along the unit direction [dir] (§7): black past max_trace_level or below adc_bailout, the sky
    when nothing is hit, else the shaded surface. [interiors] are the objects the ray is inside,
    last entered first; a [continued] ray (ior 1 transmission) does not use up a trace level. *)
