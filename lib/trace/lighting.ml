(* Local illumination: diffuse, Phong and specular from each light, light attenuation (§3, §18). *)

open Compiled

let f32 = Precision.f32
let epsilon = Precision.epsilon

let metallic_factor metallic cos_angle (c : Rgb.t) (lc : Rgb.t) =
  let x = Float.abs (acos cos_angle) /. (Float.pi /. 2.) in
  let f = (0.014567225 /. ((x -. 1.12) *. (x -. 1.12))) -. 0.011612903 in
  let f = Float.min 1. (Float.max 0. f) in
  let m = metallic *. (1. -. f) in
  let k ch = f32 (1. +. f32 (m *. f32 (ch -. 1.))) in
  Rgb.make (f32 (lc.r *. k c.r)) (f32 (lc.g *. k c.g)) (f32 (lc.b *. k c.b))

let cubic_spline lo hi p = if p < lo then 0. else if p >= hi then 1. else let s = (p -. lo) /. (hi -. lo) in (3. -. (2. *. s)) *. s *. s

let attenuation (lt : light) (p : Vec.t) (l : Vec.t) dist =
  let a =
    match lt.spread with
    | Everywhere -> 1.
    | Spot c ->
        (* the ray's cosine with the spot axis, turned round for a light in front of the point *)
        let ct = (l.x *. lt.dx) +. (l.y *. lt.dy) +. (l.z *. lt.dz) in
        let ct = if dist > 0. then -.ct else ct in
        if ct > 0. then
          let a = Float.pow ct c.tightness in
          if c.radius_cos > 0. && ct < c.radius_cos then a *. cubic_spline c.falloff_cos c.radius_cos ct else a
        else 0.
    | Beam b ->
        (* §18.2: the point's distance from the beam's axis, on the lit side of the centre *)
        let vx = p.x -. lt.lx and vy = p.y -. lt.ly and vz = p.z -. lt.lz in
        let k = (vx *. lt.dx) +. (vy *. lt.dy) +. (vz *. lt.dz) in
        if k > 0. then
          let qx = vx -. (k *. lt.dx) and qy = vy -. (k *. lt.dy) and qz = vz -. (k *. lt.dz) in
          let len = sqrt ((qx *. qx) +. (qy *. qy) +. (qz *. qz)) in
          if len < b.beam_falloff then
            let r = 1. -. (len /. b.beam_falloff) in
            let a = Float.pow r b.beam_tightness in
            if b.beam_radius > 0. && len > b.beam_radius then a *. cubic_spline 0. (1. -. (b.beam_radius /. b.beam_falloff)) r else a
          else 0.
        else 0.
  in
  if a > 0. && lt.fade then a *. (2. /. (1. +. Float.pow (dist /. lt.lfade_distance) lt.lfade_power)) else a

(* ComputeOneWhiteLightRay: dist·(−dir·l), the signed distance of the point in front of the plane
   through the centre perpendicular to dir. *)
let parallel_depth (lt : light) (l : Vec.t) dist = dist *. -.((lt.dx *. l.x) +. (lt.dy *. l.y) +. (lt.dz *. l.z))

(* One light's diffuse, phong and specular terms. *)
(* ComputeIridColour: the thin film's interference on [c], light arriving along [l] and seen along
   [d] at the point [p] with the normal [n]; the film's thickness varied by turbulence *)
let irid_turb = { Scene.turbulence = Vec.zero; octaves = 5; omega = 0.5; lambda = 2.0 }

let iridescence (sc : Compiled.t) (s : surface) (l : Vec.t) (d : Vec.t) (n : Vec.t) (p : Vec.t) (c : Rgb.t) =
  let thickness =
    if s.irid_turb <> 0. then
      let noise = (2.0 *. Noise.turbulence irid_turb sc.noise_generator p) -. 1.0 in
      s.irid_thickness *. (1.0 +. (noise *. s.irid_turb))
    else s.irid_thickness
  in
  let w = sc.irid_wavelength in
  let cl = Float.abs (Vec.dot n l) and ce = Float.abs (Vec.dot n d) in
  let interference = 2.0 *. Float.pi *. thickness *. (cl +. ce) in
  let k wl = f32 (1.0 +. (s.irid *. cos (interference /. wl))) in
  Rgb.make (f32 (c.r *. k w.r)) (f32 (c.g *. k w.g)) (f32 (c.b *. k w.b))

type memo = { mutable seen : (int * Rgb.t) list; on : bool }

let memo (_ : Compiled.t) = { seen = []; on = true }

(* no cache: every test sends its feeler (a plain texture tests each light once anyway) *)
let no_memo = { seen = []; on = false }

(* the light colour cache of ComputeOneDiffuseLight: one feeler per light for every layer and
   entry of the texture shaded at this point (kept out of [light_terms], which stays small enough
   to be inlined) *)
let cached_feeler ctx (m : memo) light ~slot p ng e l dist interiors lc =
  match List.assq_opt light m.seen with
  | Some c -> c
  | None ->
      let c = Shadow.feeler ctx ~slot p ng e l dist interiors lc in
      m.seen <- (light, c) :: m.seen;
      c

(* crand: the worker's next POV_rand value times crand off the diffuse intensity [i] *)
let crand_intensity ctx (s : surface) i = i -. (Pov_rand.next ctx.Context.crand *. s.crand)

let[@inline] light_terms ctx ~memo ~light ~slot ~di (s : surface) (p : Vec.t) (n : Vec.t) ng e (d : Vec.t) interiors (lt : light) : Rgb.t =
  let acc = Rgb.black in
  let lvx = lt.lx -. p.x and lvy = lt.ly -. p.y and lvz = lt.lz -. p.z in
  let dist = sqrt ((lvx *. lvx) +. (lvy *. lvy) +. (lvz *. lvz)) in
  (* ComputeOneWhiteLightRay: VInverseScaleEq, times the reciprocal of the distance; the last bit
     decides knife-edge shadow rays, such as one through faces shared by CSG members *)
  let k = 1. /. dist in
  let l = Vec.make (lvx *. k) (lvy *. k) (lvz *. k) in
  (* §18.3: a parallel light's ray runs along −dir, as far as the plane through the centre *)
  let dist = if lt.parallel then parallel_depth lt l dist else dist in
  let l = if lt.parallel then Vec.make (-.lt.dx) (-.lt.dy) (-.lt.dz) else l in
  let a = attenuation lt p l dist in
  let lc =
    if a <> 1. then Rgb.make (f32 (lt.lcolour.r *. a)) (f32 (lt.lcolour.g *. a)) (f32 (lt.lcolour.b *. a)) else lt.lcolour
  in
  let small (c : Rgb.t) bound = Float.abs c.r < bound && Float.abs c.g < bound && Float.abs c.b < bound in
  if small lc epsilon then Rgb.black
  else
    let nl = Vec.dot n l in
    (* §16.6: double_illuminate skips the test of the side the light is on *)
    if (not di) && nl < epsilon then Rgb.black
    else
      (* the shadow feeler; a point behind a parallel light's plane is never shadowed (§18.3) *)
      let lc =
        if lt.shadowless || dist <= 0. then lc
        else
          if not memo.on then Shadow.feeler ctx ~slot p ng e l dist interiors lc
          else cached_feeler ctx memo light ~slot p ng e l dist interiors lc
      in
      if Float.abs lc.r <= epsilon && Float.abs lc.g <= epsilon && Float.abs lc.b <= epsilon then Rgb.black
      else
        let acc =
          (* diffuse: the colour times (N·L)^brilliance *)
          if s.diffuse > 0. then
            let anl = Float.abs nl in
            let i = (if s.brilliance = 1. then anl else Float.pow anl s.brilliance) *. (s.diffuse *. s.att) in
            let i = if s.crand > 0. then crand_intensity ctx s i else i in
            Rgb.make
              (f32 (acc.r +. f32 (f32 (s.colour.r *. i) *. lc.r)))
              (f32 (acc.g +. f32 (f32 (s.colour.g *. i) *. lc.g)))
              (f32 (acc.b +. f32 (f32 (s.colour.b *. i) *. lc.b)))
          else acc
        in
        let acc =
          if lt.shadowless then acc (* §3.3: fill lights give no highlights *)
          else
            let hl = if s.metallic <> 0. then metallic_factor s.metallic nl s.colour lc else lc in
            let acc =
              (* Phong: the mirror direction's cosine with L, to the phong_size *)
              if s.phong > 0. then
                let dn = Vec.dot d n in
                let r = Vec.madd d (-2. *. dn) n in
                let c = Vec.dot r l in
                if c > 0. && (s.phong_size < 60. || c > 0.0008) then
                  let i = s.phong *. Float.pow c s.phong_size in
                  Rgb.make (f32 (acc.r +. f32 (i *. hl.r))) (f32 (acc.g +. f32 (i *. hl.g))) (f32 (acc.b +. f32 (i *. hl.b)))
                else acc
              else acc
            in
            (* specular: the halfway vector's cosine with N, to 1/roughness *)
            if s.specular > 0. then
              let h = Vec.scale 0.5 (Vec.sub l d) in
              let hlen = Vec.length h in
              if hlen > 0. then
                let c = Vec.dot h n /. hlen in
                if c > 0. then
                  let i = s.specular *. Float.pow c s.spec_exp in
                  Rgb.make (f32 (acc.r +. f32 (i *. hl.r))) (f32 (acc.g +. f32 (i *. hl.g))) (f32 (acc.b +. f32 (i *. hl.b)))
                else acc
              else acc
            else acc
        in
        (* the film's interference tints what this light gave *)
        if s.irid > 0. then iridescence ctx.Context.scene s l d n p acc else acc

let[@inline] add_lights ctx ~memo ~level ~di s p n ng e d interiors (acc : Rgb.t) =
  let lights = ctx.Context.scene.lights in
  let acc = ref acc in
  for k = 0 to Array.length lights - 1 do
    let slot = Context.cache_slot ~level k in
    let t = light_terms ctx ~memo ~light:k ~slot ~di s p n ng e d interiors lights.(k) in
    let a = !acc in
    acc := Rgb.make (f32 (a.r +. t.r)) (f32 (a.g +. t.g)) (f32 (a.b +. t.b))
  done;
  !acc
