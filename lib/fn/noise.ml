(* POV-Ray 3.7's noise and turbulence (texture.cpp), and the random table its patterns and warps
   index (randomsequences.cpp). Every table is built once, below, when the module is loaded, and
   never written again. The arithmetic follows texture.cpp operation for operation: the same sums
   in the same order, C's truncating (int) casts, its 32-bit wrap-around and its masks, so the
   values are POV-Ray's to the last bit. The functions are written to allocate nothing but their
   result (and one three-float scratch record for the vector noise): the helpers are [@inline]
   so that their floats stay unboxed. *)

(* ---------------------------------------------------------------------------------------------- *)
(* C arithmetic *)

(* The linear congruential step every table below is drawn with: next = next·1812433253 + 12345,
   kept to 32 bits as C's int does (OCaml's 63-bit product wraps too, keeping the low 32 bits). *)
let[@inline] lcg_step n = ((n * 1812433253) + 12345) land 0xFFFFFFFF

(* The 15-bit value C takes from a step: ((int)(next >> 16) & 0x7FFF), bits 16 to 30. *)
let[@inline] lcg_bits n = (n lsr 16) land 0x7FFF

type turb = { turbulence : Vec.t; octaves : int; omega : float; lambda : float }

(* C's (int) cast of a double on x86-64 (cvttsd2si): truncation toward zero, and the "integer
   indefinite" 0x80000000 for NaN and for anything outside the 32-bit range. *)

let c_int = C_float.c_int

(* ---------------------------------------------------------------------------------------------- *)
(* The hash table: a permutation of 0…4095 by 4096 LCG swaps from 0, then repeated once, so that
   two-level lookups up to 8191 need no mask (InitTextureTable). *)

let hash_table =
  let h = Array.init 8192 (fun i -> i land 0xFFF) in
  let next = ref 0 in
  for i = 4095 downto 0 do
    next := lcg_step !next;
    let j = lcg_bits !next mod 4096 in
    let t = h.(i) in
    h.(i) <- h.(j);
    h.(j) <- t
  done;
  Array.blit h 0 h 4096 4096;
  h

let[@inline] hash i = Array.unsafe_get hash_table i
let[@inline] hash2d a b = hash (hash a lxor b)
let[@inline] hash3d a b c = hash (hash (hash (a land 0xFFF) lxor (b land 0xFFF)) lxor (c land 0xFFF))

(* ---------------------------------------------------------------------------------------------- *)
(* RTable: 267 pseudo-random values; each even slot holds one, the odd slot after it its half
   (Initialize_Noise fills the odd slots). A lattice point's hash picks an even slot m; its
   contribution reads m+1 (the constant) and m+2, m+4, m+6 (the gradient); the vector noise reads
   m+8… and m+16… for its y and z. *)

let rtable_values =
  [|
    -1.; 0.604974; -0.937102; 0.414115; 0.576226; -0.0161593; 0.432334; 0.103685; 0.590539; 0.0286412;
    0.46981; -0.84622; -0.0734112; -0.304097; -0.40206; -0.210132; -0.919127; 0.652033; -0.83151;
    -0.183948; -0.671107; 0.852476; 0.043595; -0.404532; 0.75494; -0.335653; 0.618433; 0.605707;
    0.708583; -0.477195; 0.899474; 0.490623; 0.221729; -0.400381; -0.853727; -0.932586; 0.659113;
    0.961303; 0.325948; -0.750851; 0.842466; 0.734401; -0.649866; 0.394491; -0.466056; -0.434073;
    0.109026; 0.0847028; -0.738857; 0.241505; 0.16228; -0.71426; -0.883665; -0.150408; -0.90396;
    -0.686549; -0.785214; 0.488548; 0.0246433; 0.142473; -0.602136; 0.375845; -0.00779736; 0.498955;
    -0.268147; 0.856382; -0.386007; -0.596094; -0.867735; -0.570977; -0.914366; 0.28896; 0.672206;
    -0.233783; 0.94815; 0.895262; 0.343252; -0.173388; -0.767971; -0.314748; 0.824308; -0.342092;
    0.721431; -0.24004; -0.63653; 0.553277; 0.376272; 0.158984; -0.452659; 0.396323; -0.420676;
    -0.454154; 0.122179; 0.295857; 0.0664225; -0.202075; -0.724788; 0.453513; 0.224567; -0.908812;
    0.176349; -0.320516; -0.697139; 0.742702; -0.900786; 0.471489; -0.133532; 0.119127; -0.889769;
    -0.23183; -0.669673; -0.046891; -0.803433; -0.966735; 0.475578; -0.652644; 0.0112459; -0.730007;
    0.128283; 0.145647; -0.619318; 0.272023; 0.392966; 0.646418; -0.0207675; -0.315908; 0.480797;
    0.535668; -0.250172; -0.83093; -0.653773; -0.443809; 0.119982; -0.897642; 0.89453; 0.165789;
    0.633875; -0.886839; 0.930877; -0.537194; 0.587732; 0.722011; -0.209461; -0.0424659; -0.814267;
    -0.919432; 0.280262; -0.66302; -0.558099; -0.537469; -0.598779; 0.929656; -0.170794; -0.537163;
    0.312581; 0.959442; 0.722652; 0.499931; 0.175616; -0.534874; -0.685115; 0.444999; 0.17171;
    0.108202; -0.768704; -0.463828; 0.254231; 0.546014; 0.869474; 0.875212; -0.944427; 0.130724;
    -0.110185; 0.312184; -0.33138; -0.629206; 0.0606546; 0.722866; -0.0979477; 0.821561; 0.0931258;
    -0.972808; 0.0318151; -0.867033; -0.387228; 0.280995; -0.218189; -0.539178; -0.427359; -0.602075;
    0.311971; 0.277974; 0.773159; 0.592493; -0.0331884; -0.630854; -0.269947; 0.339132; 0.581079;
    0.209461; -0.317433; -0.284993; 0.181323; 0.341634; 0.804959; -0.229572; -0.758907; -0.336721;
    0.605463; -0.991272; -0.0188754; -0.300191; 0.368307; -0.176135; -0.3832; -0.749569; 0.62356;
    -0.573938; 0.278309; -0.971313; 0.839994; -0.830686; 0.439078; 0.66128; 0.694514; 0.0565042;
    0.54342; -0.438804; -0.0228428; -0.687068; 0.857267; 0.301991; -0.494255; -0.941039; 0.775509;
    0.410575; -0.362081; -0.671534; -0.348379; 0.932433; 0.886442; 0.868681; -0.225666; -0.062211;
    -0.0976425; -0.641444; -0.848112; 0.724697; 0.473503; 0.998749; 0.174701; 0.559625; -0.029099;
    -0.337392; -0.958129; -0.659785; 0.236042; -0.246937; 0.659449; -0.027512; 0.821897; -0.226215;
    0.0181735; 0.500481; -0.420127; -0.427878; 0.566186;
  |]

let rtable =
  assert (Array.length rtable_values = 267);
  Array.init (2 * 267) (fun i -> if i land 1 = 0 then rtable_values.(i / 2) else rtable_values.(i / 2) *. 0.5)

let[@inline] rt i = Array.unsafe_get rtable i

(* The even RTable slot of lattice point (hash of x and y, z): Hash1dRTableIndex. *)
let[@inline] rslot xy_hash iz = (hash (xy_hash lxor iz) land 0xFF) * 2

(* One lattice point's share: weight · (constant + gradient · offset), summed in POV-Ray's order
   (INCRSUMP). *)
let[@inline] share m s x y z = s *. (rt (m + 1) +. (rt (m + 2) *. x) +. (rt (m + 4) *. y) +. (rt (m + 6) *. z))

(* ---------------------------------------------------------------------------------------------- *)
(* The lattice cell of one coordinate (the "JB fix" of texture.cpp): the integer below [x] (a
   negative [x] is moved down by 1 − 1e-10 before truncation, so an exact negative integer stays
   its own cell), offset by MINX = −10000 and masked to 12 bits. *)

let one_minus_epsilon = 1. -. 1e-10
let min_lattice = -10000

let[@inline] cell x = if x >= 0. then c_int x else c_int (x -. one_minus_epsilon)
let[@inline] cell_index c = (c - min_lattice) land 0xFFF

let[@inline] s_curve a = a *. a *. (3.0 -. (2.0 *. a))

(* ---------------------------------------------------------------------------------------------- *)
(* Perlin's "solid noise" (noise generator 3): 2048 random unit gradients and a permutation of
   0…2048, both drawn with the LCG from 1 and repeated so that no lookup needs a mask
   (InitSolidNoise). The permutation's slot 2048 starts at 0 as C's static array does. *)

let noise_entries = 2048
let rollover = 10000000.023157213

let solid_gradients, solid_permutation =
  let g = Array.make (3 * 2 * (noise_entries + 1)) 0. in
  let p = Array.make (2 * (noise_entries + 1)) 0 in
  let next = ref 1 in
  let v = Array.make 3 0. in
  for i = 0 to noise_entries - 1 do
    let rec draw () =
      for j = 0 to 2 do
        next := lcg_step !next;
        v.(j) <- float ((lcg_bits !next mod (noise_entries lsl 1)) - noise_entries) /. float noise_entries
      done;
      let s = (v.(0) *. v.(0)) +. (v.(1) *. v.(1)) +. (v.(2) *. v.(2)) in
      if s > 1.0 || s < 1.0e-5 then draw () else s
    in
    let s = 1.0 /. sqrt (draw ()) in
    for j = 0 to 2 do
      g.((3 * i) + j) <- v.(j) *. s
    done
  done;
  for i = 0 to noise_entries - 1 do
    p.(i) <- i
  done;
  let i = ref noise_entries in
  while !i > 0 do
    let k = p.(!i) in
    next := lcg_step !next;
    let j = lcg_bits !next mod noise_entries in
    p.(!i) <- p.(j);
    p.(j) <- k;
    i := !i - 2
  done;
  for i = 0 to noise_entries + 1 do
    p.(noise_entries + i) <- p.(i);
    for j = 0 to 2 do
      g.((3 * (noise_entries + i)) + j) <- g.((3 * i) + j)
    done
  done;
  (g, p)

let[@inline] perm i = Array.unsafe_get solid_permutation i
let[@inline] grad i = Array.unsafe_get solid_gradients i

(* The gradient at permuted slot [b] dotted with the offset (rx, ry, rz) (NoiseValueAt). *)
let[@inline] grad_dot b rx ry rz = (rx *. grad (3 * b)) +. (ry *. grad ((3 * b) + 1)) +. (rz *. grad ((3 * b) + 2))

let[@inline] lerp t a b = a +. (t *. (b -. a))

let[@inline] solid_noise x y z =
  let tx = x +. rollover and ty = y +. rollover and tz = z +. rollover in
  let itx = c_int (floor tx) and ity = c_int (floor ty) and itz = c_int (floor tz) in
  let bx0 = itx land (noise_entries - 1) and by0 = ity land (noise_entries - 1) and bz0 = itz land (noise_entries - 1) in
  let bx1 = (bx0 + 1) land (noise_entries - 1) in
  let by1 = (by0 + 1) land (noise_entries - 1) in
  let bz1 = (bz0 + 1) land (noise_entries - 1) in
  let rx0 = tx -. float itx and ry0 = ty -. float ity and rz0 = tz -. float itz in
  let rx1 = rx0 -. 1.0 and ry1 = ry0 -. 1.0 and rz1 = rz0 -. 1.0 in
  let i = perm bx0 and j = perm bx1 in
  let b00 = perm (i + by0) and b10 = perm (j + by0) in
  let b01 = perm (i + by1) and b11 = perm (j + by1) in
  let sx = s_curve rx0 and sy = s_curve ry0 and sz = s_curve rz0 in
  let a = lerp sx (grad_dot (b00 + bz0) rx0 ry0 rz0) (grad_dot (b10 + bz0) rx1 ry0 rz0) in
  let b = lerp sx (grad_dot (b01 + bz0) rx0 ry1 rz0) (grad_dot (b11 + bz0) rx1 ry1 rz0) in
  let c = lerp sy a b in
  let a = lerp sx (grad_dot (b00 + bz1) rx0 ry0 rz1) (grad_dot (b10 + bz1) rx1 ry0 rz1) in
  let b = lerp sx (grad_dot (b01 + bz1) rx0 ry1 rz1) (grad_dot (b11 + bz1) rx1 ry1 rz1) in
  let d = lerp sy a b in
  lerp sz c d

let[@inline] clamp01 v = if v < 0.0 then 0.0 else if v > 1.0 then 1.0 else v

(* ---------------------------------------------------------------------------------------------- *)
(* Noise (OriNoise). Generator 3 is the solid noise, scaled by 1.59 and shifted by 0.985 to
   correct its bias; 1 and 2 interpolate the RTable lattice with the S-curve, 2 then stretching
   the range [−1.05242, 0.988997] onto [0, 1], 1 (and any other number) only adding 0.5. Every
   result is clipped to [0, 1]. *)

let[@inline] noise_xyz gen x y z =
  if gen = 3 then clamp01 (0.5 *. ((1.59 *. solid_noise x y z) +. 0.985))
  else begin
    let cx = cell x and cy = cell y and cz = cell z in
    let ix = cell_index cx and iy = cell_index cy and iz = cell_index cz in
    let x_ix = x -. float cx and y_iy = y -. float cy and z_iz = z -. float cz in
    let x_jx = x_ix -. 1. and y_jy = y_iy -. 1. and z_jz = z_iz -. 1. in
    let sx = s_curve x_ix and sy = s_curve y_iy and sz = s_curve z_iz in
    let tx = 1. -. sx and ty = 1. -. sy and tz = 1. -. sz in
    let txty = tx *. ty and sxty = sx *. ty and txsy = tx *. sy and sxsy = sx *. sy in
    let ixiy = hash2d ix iy and jxiy = hash2d (ix + 1) iy in
    let ixjy = hash2d ix (iy + 1) and jxjy = hash2d (ix + 1) (iy + 1) in
    let sum = share (rslot ixiy iz) (txty *. tz) x_ix y_iy z_iz in
    let sum = sum +. share (rslot jxiy iz) (sxty *. tz) x_jx y_iy z_iz in
    let sum = sum +. share (rslot ixjy iz) (txsy *. tz) x_ix y_jy z_iz in
    let sum = sum +. share (rslot jxjy iz) (sxsy *. tz) x_jx y_jy z_iz in
    let sum = sum +. share (rslot ixiy (iz + 1)) (txty *. sz) x_ix y_iy z_jz in
    let sum = sum +. share (rslot jxiy (iz + 1)) (sxty *. sz) x_jx y_iy z_jz in
    let sum = sum +. share (rslot ixjy (iz + 1)) (txsy *. sz) x_ix y_jy z_jz in
    let sum = sum +. share (rslot jxjy (iz + 1)) (sxsy *. sz) x_jx y_jy z_jz in
    if gen = 2 then clamp01 ((sum +. 1.05242) *. 0.48985582) else clamp01 (sum +. 0.5)
  end

let noise gen (p : Vec.t) = noise_xyz gen p.x p.y p.z

(* ---------------------------------------------------------------------------------------------- *)
(* Vector noise (OriDNoise): the same lattice, three RTable gradients per point (slots m, m+8,
   m+16), the corners visited in POV-Ray's order, which differs from the scalar noise's. It does
   not depend on the noise generator. The sums go into a local record of mutable floats (unboxed),
   either replacing its contents or adding [w] times the noise (DTurbulence's octaves). *)

type acc = { mutable ax : float; mutable ay : float; mutable az : float }

let[@inline] dnoise_into acc ~replace w x y z =
  let cx = cell x and cy = cell y and cz = cell z in
  let ix = cell_index cx and iy = cell_index cy and iz = cell_index cz in
  let x_ix = x -. float cx and y_iy = y -. float cy and z_iz = z -. float cz in
  let x_jx = x_ix -. 1. and y_jy = y_iy -. 1. and z_jz = z_iz -. 1. in
  let sx = s_curve x_ix and sy = s_curve y_iy and sz = s_curve z_iz in
  let tx = 1. -. sx and ty = 1. -. sy and tz = 1. -. sz in
  let txty = tx *. ty and sxty = sx *. ty and txsy = tx *. sy and sxsy = sx *. sy in
  let ixiy = hash2d ix iy and jxiy = hash2d (ix + 1) iy in
  let ixjy = hash2d ix (iy + 1) and jxjy = hash2d (ix + 1) (iy + 1) in
  let m = rslot ixiy iz and s = txty *. tz in
  let rx = share m s x_ix y_iy z_iz and ry = share (m + 8) s x_ix y_iy z_iz and rz = share (m + 16) s x_ix y_iy z_iz in
  let m = rslot jxiy iz and s = sxty *. tz in
  let rx = rx +. share m s x_jx y_iy z_iz and ry = ry +. share (m + 8) s x_jx y_iy z_iz in
  let rz = rz +. share (m + 16) s x_jx y_iy z_iz in
  let m = rslot jxjy iz and s = sxsy *. tz in
  let rx = rx +. share m s x_jx y_jy z_iz and ry = ry +. share (m + 8) s x_jx y_jy z_iz in
  let rz = rz +. share (m + 16) s x_jx y_jy z_iz in
  let m = rslot ixjy iz and s = txsy *. tz in
  let rx = rx +. share m s x_ix y_jy z_iz and ry = ry +. share (m + 8) s x_ix y_jy z_iz in
  let rz = rz +. share (m + 16) s x_ix y_jy z_iz in
  let m = rslot ixjy (iz + 1) and s = txsy *. sz in
  let rx = rx +. share m s x_ix y_jy z_jz and ry = ry +. share (m + 8) s x_ix y_jy z_jz in
  let rz = rz +. share (m + 16) s x_ix y_jy z_jz in
  let m = rslot jxjy (iz + 1) and s = sxsy *. sz in
  let rx = rx +. share m s x_jx y_jy z_jz and ry = ry +. share (m + 8) s x_jx y_jy z_jz in
  let rz = rz +. share (m + 16) s x_jx y_jy z_jz in
  let m = rslot jxiy (iz + 1) and s = sxty *. sz in
  let rx = rx +. share m s x_jx y_iy z_jz and ry = ry +. share (m + 8) s x_jx y_iy z_jz in
  let rz = rz +. share (m + 16) s x_jx y_iy z_jz in
  let m = rslot ixiy (iz + 1) and s = txty *. sz in
  let rx = rx +. share m s x_ix y_iy z_jz and ry = ry +. share (m + 8) s x_ix y_iy z_jz in
  let rz = rz +. share (m + 16) s x_ix y_iy z_jz in
  if replace then begin
    acc.ax <- rx;
    acc.ay <- ry;
    acc.az <- rz
  end
  else begin
    acc.ax <- acc.ax +. (w *. rx);
    acc.ay <- acc.ay +. (w *. ry);
    acc.az <- acc.az +. (w *. rz)
  end

let dnoise (p : Vec.t) =
  let acc = { ax = 0.; ay = 0.; az = 0. } in
  dnoise_into acc ~replace:true 1. p.x p.y p.z;
  { Vec.x = acc.ax; y = acc.ay; z = acc.az }

(* ---------------------------------------------------------------------------------------------- *)
(* Turbulence and DTurbulence: octave i (from 2) samples the point scaled by lambda^(i−1) and
   weighs it by omega^(i−1), the powers built by repeated products as POV-Ray does. Generators 2
   and 3 use 2·noise − 0.5 per octave, the first octave's clipped to [0, 1]. *)

let turbulence (t : turb) gen (p : Vec.t) =
  let x = p.x and y = p.y and z = p.z in
  let value = ref (if gen > 1 then clamp01 ((2.0 *. noise_xyz gen x y z) -. 0.5) else noise_xyz gen x y z) in
  let lambda = t.lambda and omega = t.omega in
  let l = ref lambda and o = ref omega in
  for i = 2 to t.octaves do
    let n = noise_xyz gen (x *. !l) (y *. !l) (z *. !l) in
    (value := if gen > 1 then !value +. (!o *. ((2.0 *. n) -. 0.5)) else !value +. (!o *. n));
    if i < t.octaves then begin
      l := !l *. lambda;
      o := !o *. omega
    end
  done;
  !value

let dturbulence (t : turb) (p : Vec.t) =
  let x = p.x and y = p.y and z = p.z in
  let acc = { ax = 0.; ay = 0.; az = 0. } in
  dnoise_into acc ~replace:true 1. x y z;
  let lambda = t.lambda and omega = t.omega in
  let l = ref lambda and o = ref omega in
  for i = 2 to t.octaves do
    dnoise_into acc ~replace:false !o (x *. !l) (y *. !l) (z *. !l);
    if i < t.octaves then begin
      l := !l *. lambda;
      o := !o *. omega
    end
  done;
  { Vec.x = acc.ax; y = acc.ay; z = acc.az }

(* ---------------------------------------------------------------------------------------------- *)
(* The random table: RandomDoubleSequence(0, 1, 32768) is the first 32768 outputs of Boost's
   mt19937 with its default seed 5489, each taken through uniform_real<double>(0, 1), which (Boost
   1.47 and later, for a 32-bit engine) is u / 2³² · (1 − 0) + 0. *)

let random_table =
  let n = 624 and m = 397 in
  let mt = Array.make n 0 in
  mt.(0) <- 5489;
  for i = 1 to n - 1 do
    let prev = mt.(i - 1) in
    mt.(i) <- ((1812433253 * (prev lxor (prev lsr 30))) + i) land 0xFFFFFFFF
  done;
  let index = ref n in
  let twist () =
    for i = 0 to n - 1 do
      let y = (mt.(i) land 0x80000000) lor (mt.((i + 1) mod n) land 0x7FFFFFFF) in
      let v = mt.((i + m) mod n) lxor (y lsr 1) in
      mt.(i) <- (if y land 1 = 1 then v lxor 0x9908B0DF else v)
    done;
    index := 0
  in
  let next () =
    if !index >= n then twist ();
    let y = mt.(!index) in
    incr index;
    let y = y lxor (y lsr 11) in
    let y = y lxor ((y lsl 7) land 0x9D2C5680) in
    let y = y lxor ((y lsl 15) land 0xEFC60000) in
    (y lxor (y lsr 18)) land 0xFFFFFFFF
  in
  Array.init 32768 (fun _ ->
      let u = next () in
      (float u /. 4294967296.0 *. (1.0 -. 0.0)) +. 0.0)

let random_double i = Array.unsafe_get random_table (i land 32767)

(* ---------------------------------------------------------------------------------------------- *)
(* The waves and ripples sources (Initialize_Waves): source i is the vector noise at <i, 0, 0>,
   normalised by division; frequency i is the i-th draw of the LCG from −560851967, scaled to
   [0.01, 1.01). Neither depends on how many waves a scene asks for. *)

let wave_source i =
  let d = dnoise { Vec.x = float i; y = 0.; z = 0. } in
  let l = sqrt ((d.x *. d.x) +. (d.y *. d.y) +. (d.z *. d.z)) in
  if l <> 0. then { Vec.x = d.x /. l; y = d.y /. l; z = d.z /. l } else d

let wave_frequency i =
  let rec draw next k = if k = 0 then next else draw (lcg_step next) (k - 1) in
  let next = draw (-560851967 land 0xFFFFFFFF) (i + 1) in
  (float (lcg_bits next) *. 0.000030518509476) +. 0.01

(* source i does not depend on how many there are: the first 64 are tabled, more are made when
   asked for *)
let tabled_waves = 64
let source_table = Array.init tabled_waves wave_source
let frequency_table = Array.init tabled_waves wave_frequency
let wave_sources n = if n <= tabled_waves then source_table else Array.init n wave_source
(* the frequencies in one pass of the LCG *)
let frequencies_upto n =
  let t = Array.make n 0. in
  let next = ref (-560851967 land 0xFFFFFFFF) in
  for i = 0 to n - 1 do
    next := lcg_step !next;
    t.(i) <- (float (lcg_bits !next) *. 0.000030518509476) +. 0.01
  done;
  t

let wave_frequencies n = if n <= tabled_waves then frequency_table else frequencies_upto n

(* ---------------------------------------------------------------------------------------------- *)
(* The two waveforms of texture.cpp that patterns and normals use. cycloidal is sin(2π·frac v),
   the fraction taken by way of 50000ths; below 0 it is computed from −v, as −cycloidal(−v), which
   rounds differently from taking the fraction of v itself. triangle_wave rises from 0 to 1 over
   [0, 0.5) and falls back over [0.5, 1). *)

let two_pi = 2. *. Float.pi

let cycloidal v =
  if v >= 0.0 then sin ((v -. floor v) *. 50000.0 /. 50000.0 *. two_pi)
  else 0.0 -. sin ((0.0 -. (v +. floor (0.0 -. v))) *. 50000.0 /. 50000.0 *. two_pi)

let triangle_wave v =
  let offset = if v >= 0.0 then v -. floor v else v +. 1.0 +. floor (Float.abs v) in
  if offset >= 0.5 then 2.0 *. (1.0 -. offset) else 2.0 *. offset
