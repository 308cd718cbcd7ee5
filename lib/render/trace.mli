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
  qhits : float array;
  torus : Torus.work;
  ghits : hits;
  near : float array;
  walk_lim : float array;
  best : best;
}
(** What a trace reads: the compiled scene, the worker's statistics, scratch space (the last
    hit's depth and mesh face, traversal stacks, a box's crossings, a CSG's hits and member hit,
    the hits of one cylinder, cone or disc, a torus's quartic, a text letter's crossings, the nearest-hit search's best depth,
    reciprocal direction, least depth, walk limit and best object) and POV-Ray's shadow cache (§4: per light, the opaque object that
    last blocked it), all private to one worker; and the mode's limits: the
    depths shapes accept, the nearest depth any ray accepts (1e-4, §2.1), and whether secondary
    rays leave from points lifted off the surface (robust mode). *)

and best = { mutable best_id : int; mutable best_face : int }
(** The nearest-hit search's best object so far and its mesh face (−1 for none). *)

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
    infinity; for a mesh the face, for a box the side (1–6: X−, X+, Y−, Y+, Z−, Z+), for a
    cylinder or cone the part (1 base, 2 cap, 3 side), is left in [ctx.sub.(0)]. Of a cylinder's,
    cone's or disc's equal depths the last listed wins, as in POV-Ray. *)

val cone_hits : ctx -> Compiled.cone -> Vec.t -> Vec.t -> float array -> int
(** [cone_hits ctx c o d out] lists every crossing of the ray from [o] along the unit direction
    [d] with the cylinder or cone [c] within its own limits (§15.2, §15.3: canonical depths
    1e-9 < s < 1e7, divided by the length of the canonical direction), in POV-Ray's order: the
    side's roots, then the cap (z = 1), then the base (z = dist). Crossing [i] is written as the
    world depth [out.(2i)] and the part [out.(2i+1)] (1. base, 2. cap, 3. side); the result is how
    many there are (at most 4, so [out] needs 8 floats). No minimum depth is applied. *)

val disc_hits : ctx -> Compiled.disc -> Vec.t -> Vec.t -> float array -> int
(** [disc_hits ctx dc o d out] is [cone_hits] for a disc (§15.4): 0 or 1 crossing, written as
    ([out.(0)] = world depth within 1e-6 … 1e7, [out.(1)] = 0.). *)

val torus_hits : ctx -> Torus.t -> Vec.t -> Vec.t -> float array -> int
(** [torus_hits ctx t o d out] writes every depth at which the ray from [o] along the unit [d]
    crosses the torus [t] within its limits (beyond 1e-4 in world units, below 1e7; §15.5) into
    [out] (room for 4), in POV-Ray's order, and returns their number; the torus statistics are
    counted. For CSG, which needs every crossing. *)

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
