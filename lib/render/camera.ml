(* The camera: one case per projection, each with its function from an image position to a ray
   (docs/povray-rules.md §1.4, §18.4). What does not depend on the position is worked out once. *)

open Compiled

(* The image's size as §1.4's formula divides by it: W, H and H − 1 as floats *)
type screen = { w : float; h : float; h1 : float }

(* x0 = (x + 0.5)/W − 0.5 and y0 = ((H − 1) − (y − 0.5))/H − 0.5, in this order of operations *)
let[@inline] x0 s x = ((x +. 0.5) /. s.w) -. 0.5
let[@inline] y0 s y = ((s.h1 -. (y -. 0.5)) /. s.h) -. 0.5

type perspective = {
  location : Vec.t;
  direction : Vec.t;
  right : Vec.t;
  up : Vec.t;
  pscreen : screen;
  start : int list;  (* the interiors holding the location, in the mode's order *)
}

type orthographic = {
  centre : Vec.t;  (* the location: the screen's centre *)
  across : Vec.t;  (* right *)
  upward : Vec.t;  (* up *)
  along : Vec.t;  (* the direction, normalised: every ray's *)
  oscreen : screen;
  holders : obj array;  (* the objects whose box a ray's origin may lie in ([screen_holders]) *)
  objects : obj array;  (* the scene's objects, for the robust mode's order *)
  robust : bool;
}

type t = Perspective of perspective | Orthographic of orthographic

let make (sc : Compiled.t) ~robust ~width ~height =
  let cam = sc.camera in
  let screen = { w = float_of_int width; h = float_of_int height; h1 = float_of_int (height - 1) } in
  match cam.projection with
  | Perspective ->
      Perspective
        {
          location = cam.location;
          direction = cam.direction;
          right = cam.right;
          up = cam.up;
          pscreen = screen;
          start = (if robust then sc.robust_start_interiors else sc.start_interiors);
        }
  | Orthographic ->
      Orthographic
        {
          centre = cam.location;
          across = cam.right;
          upward = cam.up;
          along = Vec.normalize cam.direction;
          oscreen = screen;
          holders = sc.screen_holders;
          objects = sc.objects;
          robust;
        }

(* §1.4: every ray leaves the location, along direction + x0·right + y0·up, normalised *)
let perspective p ctx x y k =
  let x0 = x0 p.pscreen x and y0 = y0 p.pscreen y in
  let d = p.direction and r = p.right and u = p.up in
  let dir =
    Vec.normalize
      (Vec.make
         (d.x +. (x0 *. r.x) +. (y0 *. u.x))
         (d.y +. (x0 *. r.y) +. (y0 *. u.y))
         (d.z +. (x0 *. r.z) +. (y0 *. u.z)))
  in
  k ctx p.start p.location dir

(* §18.4: every ray leaves its own point of the screen, location + x0·right + y0·up, along the
   direction; so each has its own interior list *)
let orthographic o (ctx : Context.t) x y k =
  let x0 = x0 o.oscreen x and y0 = y0 o.oscreen y in
  let l = o.centre and r = o.across and u = o.upward in
  let origin = Vec.make (l.x +. (x0 *. r.x) +. (y0 *. u.x)) (l.y +. (x0 *. r.y) +. (y0 *. u.y)) (l.z +. (x0 *. r.z) +. (y0 *. u.z)) in
  let interiors = Interiors.at o.holders ctx.shapes.mesh_stack origin in
  let interiors = if o.robust then Interiors.innermost_first o.objects interiors else interiors in
  k ctx interiors origin o.along

let ray cam ctx x y k = match cam with Perspective p -> perspective p ctx x y k | Orthographic o -> orthographic o ctx x y k
