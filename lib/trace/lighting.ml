(* Local illumination: diffuse, Phong and specular from each sample of each light, each through its
   shadow feeler (§3, §18). *)

open Compiled

let f32 = Precision.f32
let epsilon = Precision.epsilon

let metallic_factor metallic cos_angle (c : Rgb.t) (lc : Rgb.t) =
  let x = Float.abs (acos cos_angle) /. (Float.pi /. 2.) in
  let f = (0.014567225 /. ((x -. 1.12) *. (x -. 1.12))) -. 0.011612903 in
  let f = Floats.min 1. (Floats.max 0. f) in
  let m = metallic *. (1. -. f) in
  let k ch = f32 (1. +. f32 (m *. f32 (ch -. 1.))) in
  Rgb.make (f32 (lc.r *. k c.r)) (f32 (lc.g *. k c.g)) (f32 (lc.b *. k c.b))

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

(* the light colour cache of ComputeOneDiffuseLight: one feeler per light for every layer and
   entry of the texture shaded at this point (kept out of [local], which is inlined) *)
let cached_feeler ctx (h : Hit.t) light ~slot (smp : Light.sample) lc =
  let m = h.memo in
  match List.assq_opt light m.seen with
  | Some c -> c
  | None ->
      let c = Shadow.feeler ctx h ~slot smp lc in
      m.seen <- (light, c) :: m.seen;
      c

(* crand: POV_rand times crand off the diffuse intensity [i] *)
let crand_intensity ctx (s : surface) i = i -. (Pov_rand.next ctx.Context.crand *. s.crand)

(* ComputeOneDiffuseLight for every sample of every light: the sums are kept in floats, each
   light's terms summed first (from 0, in the order diffuse, phong, specular) and then added to the
   colour, in single precision as POV-Ray sums them. *)
let[@inline] local ctx (h : Hit.t) (s : surface) (n : Vec.t) =
  if not s.lit then s.emitted
  else begin
    let p = h.point and d = h.ray.dir in
    let lights = ctx.Context.scene.lights and smp = ctx.Context.sample in
    let r = ref s.emitted.r and g = ref s.emitted.g and b = ref s.emitted.b in
    for k = 0 to Array.length lights - 1 do
      let light = lights.(k) in
      let slot = Context.cache_slot ~level:h.level k in
      let lr = ref 0. and lg = ref 0. and lb = ref 0. in
      for j = 0 to Light.samples light - 1 do
        Light.sample light p j smp;
        let lx = smp.dx and ly = smp.dy and lz = smp.dz in
        let lc = Light.colour light smp in
        let nl = (n.x *. lx) +. (n.y *. ly) +. (n.z *. lz) in
        (* a light too dim to matter; §16.6: double_illuminate skips the test of the side the light
           is on *)
        if (not (Float.abs lc.r < epsilon && Float.abs lc.g < epsilon && Float.abs lc.b < epsilon)) && (h.obj.double_illuminate || not (nl < epsilon)) then begin
          (* the shadow feeler; a point behind a parallel light's plane is never shadowed (§18.3) *)
          let lc =
            if light.shadowless || smp.dist <= 0. then lc
            else if not h.memo.on then Shadow.feeler ctx h ~slot smp lc
            else cached_feeler ctx h k ~slot smp lc
          in
          if not (Float.abs lc.r <= epsilon && Float.abs lc.g <= epsilon && Float.abs lc.b <= epsilon) then begin
            (* diffuse: the colour times (N·L)^brilliance *)
            if s.diffuse > 0. then begin
              let anl = Float.abs nl in
              let i = (if s.brilliance = 1. then anl else Float.pow anl s.brilliance) *. (s.diffuse *. s.att) in
              let i = if s.crand > 0. then crand_intensity ctx s i else i in
              lr := f32 (!lr +. f32 (f32 (s.colour.r *. i) *. lc.r));
              lg := f32 (!lg +. f32 (f32 (s.colour.g *. i) *. lc.g));
              lb := f32 (!lb +. f32 (f32 (s.colour.b *. i) *. lc.b))
            end;
            (* §3.3: fill lights give no highlights *)
            if not light.shadowless then begin
              let hl = if s.metallic <> 0. then metallic_factor s.metallic nl s.colour lc else lc in
              (* Phong: the mirror direction R = d − 2(d·N)N's cosine with L, to the phong_size *)
              if s.phong > 0. then begin
                let m = -2. *. Vec.dot d n in
                let c = ((d.x +. (m *. n.x)) *. lx) +. ((d.y +. (m *. n.y)) *. ly) +. ((d.z +. (m *. n.z)) *. lz) in
                if c > 0. && (s.phong_size < 60. || c > 0.0008) then begin
                  let i = s.phong *. Float.pow c s.phong_size in
                  lr := f32 (!lr +. f32 (i *. hl.r));
                  lg := f32 (!lg +. f32 (i *. hl.g));
                  lb := f32 (!lb +. f32 (i *. hl.b))
                end
              end;
              (* specular: the halfway vector H = (L − d)/2's cosine with N, to 1/roughness *)
              if s.specular > 0. then begin
                let hx = 0.5 *. (lx -. d.x) and hy = 0.5 *. (ly -. d.y) and hz = 0.5 *. (lz -. d.z) in
                let hlen = sqrt ((hx *. hx) +. (hy *. hy) +. (hz *. hz)) in
                if hlen > 0. then begin
                  let c = ((hx *. n.x) +. (hy *. n.y) +. (hz *. n.z)) /. hlen in
                  if c > 0. then begin
                    let i = s.specular *. Float.pow c s.spec_exp in
                    lr := f32 (!lr +. f32 (i *. hl.r));
                    lg := f32 (!lg +. f32 (i *. hl.g));
                    lb := f32 (!lb +. f32 (i *. hl.b))
                  end
                end
              end
            end;
            (* the film's interference tints what this light gave *)
            if s.irid > 0. then begin
              let c = iridescence ctx.Context.scene s (Vec.make lx ly lz) d n p (Rgb.make !lr !lg !lb) in
              lr := c.r;
              lg := c.g;
              lb := c.b
            end
          end
        end
      done;
      r := f32 (!r +. !lr);
      g := f32 (!g +. !lg);
      b := f32 (!b +. !lb)
    done;
    Rgb.make !r !g !b
  end
