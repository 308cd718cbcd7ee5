(* A render worker's context: the scene, the statistics, the scratch, the shadow cache, the
   facets cache, crand's stream and the room of POV-Ray's tree walk. *)

type found = { mutable id : int; mutable part : int; mutable near : bool; mutable reported : bool }
type reach = { mutable depth : float; mutable least : float; mutable inv_dx : float; mutable inv_dy : float; mutable inv_dz : float }

type t = {
  scene : Compiled.t;
  stats : Stats.t;
  shapes : Scratch.t;
  stack : float array;
  min_depth : float;
  robust : bool;
  shadow_cache : int array;
  found : found;
  reach : reach;
  crossing : Crossing.t;
  walk_limit : float array;
  facets : Normals.facets_cache;
  crand : Pov_rand.t;
  pov_room : Slab_tree.room;
  sample : Light.sample;
}

let shadow_cache (scene : Compiled.t) = Array.make (2 * max 1 (Array.length scene.lights)) (-1)

(* what the nearest-hit search starts from *)
let no_hit () = { id = -1; part = -1; near = false; reported = false }
let no_reach () = { depth = 0.; least = 0.; inv_dx = 0.; inv_dy = 0.; inv_dz = 0. }

(* the same values written into a worker's records, which its next block reuses *)
let restart (f : found) (r : reach) =
  f.id <- -1;
  f.part <- -1;
  f.near <- false;
  f.reported <- false;
  r.depth <- 0.;
  r.least <- 0.;
  r.inv_dx <- 0.;
  r.inv_dy <- 0.;
  r.inv_dz <- 0.

let make ?(robust = false) (scene : Compiled.t) stats =
  {
    scene;
    stats;
    shapes = Scratch.create ~robust stats;
    stack = Array.make 512 0.;
    min_depth = (if robust then 0. else Precision.min_isect_depth);
    robust;
    shadow_cache = shadow_cache scene;
    found = no_hit ();
    reach = no_reach ();
    crossing = Crossing.create ();
    walk_limit = [| 0. |];
    facets = Normals.facets_cache ();
    crand = Pov_rand.create ();
    pov_room = Slab_tree.room ();
    sample = Light.room ();
  }

let renew ctx ~carry stats =
  Normals.reset_facets ctx.facets;
  let shapes = Scratch.renew ctx.shapes stats in
  if not carry then Scratch.forget_iso_cache shapes;
  let shadow_cache = if carry then ctx.shadow_cache else shadow_cache ctx.scene in
  restart ctx.found ctx.reach;
  { ctx with stats; shadow_cache; shapes }

let[@inline] cache_slot ~level k = (2 * k) + if level = 1 then 0 else 1
