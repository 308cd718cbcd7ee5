(* Reflection and transmission: Fresnel, interior fade and interior lists (§4–§6). *)

open Compiled

let f32 = Precision.f32
let epsilon = Precision.epsilon

let[@inline] fade_factor fade_colour fade_distance fade_power depth (c : Rgb.t) =
  if fade_power >= 1000. then
    let k x = f32 (exp (-.f32 (1. -. x) *. (depth /. fade_distance))) in
    Rgb.make (f32 (c.r *. k fade_colour.Rgb.r)) (f32 (c.g *. k fade_colour.g)) (f32 (c.b *. k fade_colour.b))
  else
    let a = 1. +. Float.pow (depth /. fade_distance) fade_power in
    let k x = f32 (x +. f32 (f32 (1. -. x) /. a)) in
    Rgb.make (f32 (c.r *. k fade_colour.Rgb.r)) (f32 (c.g *. k fade_colour.g)) (f32 (c.b *. k fade_colour.b))

let fade obj depth c = fade_factor obj.interior.fade_colour obj.interior.fade_distance obj.interior.fade_power depth c
let fades obj = Float.abs obj.interior.fade_distance > epsilon
let rec remove id = function [] -> [] | x :: rest -> if x = id then rest else x :: remove id rest

(* §5.2: the ratio n_transmitted / n_incident seen by the Fresnel term. *)
let fresnel_ior sc obj interiors =
  match interiors with
  | [] -> obj.interior.ior
  | last :: rest ->
      if List.mem obj.iid interiors then if rest = [] then 1. /. obj.interior.ior else sc.objects.(last).interior.ior /. obj.interior.ior
      else obj.interior.ior /. sc.objects.(last).interior.ior

(* k·hi + (1 − k)·lo in single precision *)
let blend k (hi : Rgb.t) (lo : Rgb.t) =
  let k' = 1. -. k in
  Rgb.make (f32 (f32 (hi.r *. k) +. f32 (lo.r *. k'))) (f32 (f32 (hi.g *. k) +. f32 (lo.g *. k'))) (f32 (f32 (hi.b *. k) +. f32 (lo.b *. k')))

let reflectivity sc (s : surface) obj interiors ci : Rgb.t =
  let r = s.refl in
  if not r.fresnel then
    let frac = if Float.abs (r.falloff -. 1.) > epsilon then Float.pow (1. -. ci) r.falloff else 1. -. ci in
    if Float.abs frac < epsilon then r.rmin
    else if Float.abs (frac -. 1.) < epsilon then r.rmax
    else blend frac r.rmax r.rmin
  else
    let n = fresnel_ior sc obj interiors in
    let sq = (n *. n) +. (ci *. ci) -. 1. in
    if sq > 0. then
      let g = sqrt sq in
      let a = (g -. ci) /. (g +. ci) in
      let b = ((ci *. (g +. ci)) -. 1.) /. ((ci *. (g -. ci)) +. 1.) in
      let f = 0.5 *. a *. a *. (1. +. (b *. b)) in
      let f = Floats.min 1. (Floats.max 0. f) in
      blend f r.rmax r.rmin
    else r.rmax

let conserved (s : surface) (refl : Rgb.t) =
  if s.conserve && s.reflects then
    let k x = f32 (Floats.min 1. (1. -. x)) in
    Rgb.make (f32 (s.filcol.r *. k refl.r)) (f32 (s.filcol.g *. k refl.g)) (f32 (s.filcol.b *. k refl.b))
  else s.filcol

(* ComputeReflection's direction off a bent normal [n]: the mirror direction, unless it points
   below the surface by the raw normal [raw] (the "reflection bugfix" of trace.cpp): then the
   mirror direction off [raw] when it is below the bent normal's plane too, else the mirror
   direction reflected again in the raw normal's plane. Normalised last. *)
let bent_reflection (d : Vec.t) (n : Vec.t) (raw : Vec.t) =
  let r = Vec.madd d (-2. *. Vec.dot d n) n in
  let below = Vec.dot r raw in
  let r =
    if below < 0. then if Vec.dot r n < 0. then Vec.madd d (-2. *. Vec.dot d raw) raw else Vec.madd r (below *. -2.) raw
    else r
  in
  Vec.normalize r
