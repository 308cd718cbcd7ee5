(* A surface hit being shaded, and the rays that leave it. *)

open Compiled

type memo = { mutable seen : (int * Rgb.t) list; on : bool }

type lift = { geometric : Vec.t; error : float }

type t = {
  ray : Ray.t;
  obj : obj;
  part : int;
  depth : float;
  crossing : Crossing.t;
  level : int;
  point : Vec.t;
  normal : Vec.t;
  lift : lift;
  texture : texture;
  memo : memo;
  mutable pnormal : Vec.t;
}

(* no cache: every test sends its feeler (a plain texture tests each light once anyway) *)
let no_memo = { seen = []; on = false }

(* POV-Ray's mode: a secondary ray leaves from the hit point itself *)
let no_lift = { geometric = Vec.zero; error = 0. }

let[@inline] make (ctx : Context.t) (ray : Ray.t) (f : Nearest.found) ~level =
  let obj = ctx.scene.objects.(Nearest.id f) and part = Nearest.part f and depth = Nearest.depth f in
  let o = ray.origin and d = ray.dir in
  (* the hit point P and its normal N, turned toward the ray (§3.1) *)
  let crossing = Nearest.crossing f in
  let p = if ctx.robust then Shape.refine obj (Vec.madd o depth d) else Shape.hit_point ctx.shapes obj crossing o depth d in
  let n = Shape.hit_normal ctx.shapes obj part crossing p in
  let dn = Vec.dot n d in
  let texture = if obj.inner_tex = None then Surfaces.at obj part else Surfaces.seen obj part ~inside:(if obj.inverted then dn < 0. else dn > 0.) in
  let n = if dn > 0. then Vec.neg n else n in
  let lift =
    if ctx.robust then begin
      let geometric = Shape.geometric_normal ctx.shapes obj part p in
      let error = Robust.error_bound ~shift:ctx.scene.shift o p obj.mag in
      { geometric; error }
    end
    else no_lift
  in
  let memo = match texture with Plain _ when not obj.uv_mapped -> no_memo | Plain _ | Layered _ | Blended _ | Uv_mapped _ | Chosen _ | Cutaway -> { seen = []; on = true } in
  { ray; obj; part; depth; crossing; level; point = p; normal = n; lift; texture; memo; pnormal = n }

let[@inline] origin ctx h dir = Robust.origin ctx h.point h.lift.geometric h.lift.error dir

let spawn ctx h (kind : Ray.kind) ~weight ~interiors dir : Ray.t =
  let mirrored = match kind with Reflected -> true | Camera | Transmitted | Continued | Shadow -> h.ray.mirrored in
  { origin = origin ctx h dir; dir; kind; level = h.level; weight; interiors; mirrored }
