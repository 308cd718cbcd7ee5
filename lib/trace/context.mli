(** What one render worker's traces read and write: the compiled scene, which they only read, and
    everything they write: the worker's statistics, its scratch space (named fields, stored flat
    where they are floats, so the hot path allocates nothing), POV-Ray's shadow cache, its facets
    cache and crand's stream (POV-Ray's per-thread data, TraceThreadData). Nothing here is shared
    between workers. *)

type found = { mutable id : int; mutable part : int; mutable near : bool; mutable reported : bool }
(** The nearest-hit search's best object so far (−1 for none) and the part of it hit (a mesh face,
    a box side …), whether two top-level objects' hits nearly tied on the way, and whether the
    best crossing's shape reported what it found there (kept in [crossing]). After a search:
    what it found. *)

type reach = {
  mutable depth : float;  (** the best depth so far; after a search, the depth found *)
  mutable least : float;  (** the least depth the search accepts *)
  mutable inv_dx : float;
  mutable inv_dy : float;
  mutable inv_dz : float;  (** the reciprocal of the ray's direction, for the box tests *)
}
(** The nearest-hit search's floats. *)

type t = {
  scene : Compiled.t;
  stats : Stats.t;
  shapes : Scratch.t;  (** the intersection routines' scratch *)
  stack : float array;  (** traversal room of the scene's hierarchy *)
  min_depth : float;  (** the nearest depth any ray accepts: 1e-4 (§2.1), 0 in the robust mode *)
  robust : bool;  (** secondary rays leave from points lifted off the surface (robust mode) *)
  shadow_cache : int array;
      (** §4: per light and kind of level, the opaque object that last blocked it, or −1 *)
  found : found;
  reach : reach;
  crossing : Crossing.t;
      (** the report of the best crossing so far (a julia fractal's, a bicubic patch's, a
          parametric surface's: {!Crossing}), copied from the scratch's when the best is
          replaced by a crossing that has one ([found.reported]); after a search, the found
          crossing's. The next search writes it again: a hit keeps its own copy ({!Hit}) *)
  walk_limit : float array;  (** the limit of the hierarchy's walk (one float) *)
  facets : Normals.facets_cache;
      (** POV-Ray's facets cache, which a render thread keeps for every facets normal it meets;
          emptied at the start of each block ({!renew}), as a fresh thread's would be *)
  crand : Pov_rand.t;
      (** crand's random stream: made with the worker, it runs on from block to block in the
          order the worker renders them and is never reset; a scene with crand is rendered by one
          worker, so that its order is POV-Ray's one-thread order *)
  pov_room : Slab_tree.room;  (** the room of POV-Ray's bounding-tree search ({!Compiled.order}) *)
  sample : Light.sample;  (** the light sample local illumination writes and reads ({!Light.sample}) *)
}

val shadow_cache : Compiled.t -> int array
(** [shadow_cache scene] is an empty shadow cache for [scene] (as at the start of a POV-Ray render
    thread). *)

val make : ?robust:bool -> Compiled.t -> Stats.t -> t
(** [make ?robust scene stats] is a context for one render worker, counting into [stats], as a
    new POV-Ray render thread starts: an empty shadow cache, the isosurfaces' state of a thread
    that has searched nothing, crand's stream at its start; [robust] (default false) selects the
    robust mode's limits instead of POV-Ray's. A render worker makes one for its first block and
    {!renew}s it for each next one. *)

val renew : t -> carry:bool -> Stats.t -> t
(** [renew ctx ~carry stats] is the context of the worker's next block, counting into [stats]: it
    keeps [ctx]'s rooms and caches (allocated once per worker, not per block: a 67,108,864×1 image
    has two million blocks), crand's stream and what it keeps for each isosurface, empties the
    facets cache, and starts the search as {!make} does. With [carry] the shadow cache and the
    isosurfaces' cache carry over from the block before, as in POV-Ray's one render thread;
    without it they start empty, as a new thread's. [ctx] is not used afterwards. *)

val cache_slot : level:int -> int -> int
(** [cache_slot ~level k] is light [k]'s shadow-cache slot for the shadow tests made while
    shading a hit at trace [level] (1 for a camera ray's hit): POV-Ray keeps two per light, one
    for the shadow rays of level-1 hits (lightSourceLevel1ShadowCache, used where its trace level,
    raised by the shadow ray itself, is 2: the even slot 2k) and one for those of every deeper
    level (2k + 1). A test from a level-1 hit whose slot is empty tries the other one
    ({!Shadow.feeler}). *)
