(* The noise-based internal functions of POV-Ray 3.7 (fnintern.cpp): f_hetero_mf, f_ridge,
   f_ridged_mf, f_noise3d and f_noise_generator, on the project's Noise (texture.cpp's Noise,
   bit-exact). The fractal ones take their generator from their last parameter, (int)p & 3, where
   0 behaves as 1 (Noise tests only for 2 and 3); f_noise3d uses the scene's. Argument array: x, y,
   z at 0, 1, 2, then the parameters from 3. *)

let c_int = C_float.c_int
let fmax = C_float.fmax

(* the generator a parameter names: (int)p & 3 *)
let[@inline] generator p = c_int p land 3

let[@inline] point a = Vec.make a.(0) a.(1) a.(2)

(* ---------------------------------------------------------------------------------------------- *)
(* f_hetero_mf: parameters H, lacunarity, octaves, offset, T, generator *)

let hetero_mf a =
  let h = a.(3) and lacunarity = a.(4) and octaves = a.(5) and offset = a.(6) in
  let gen = generator a.(8) in
  let increment v = (Noise.noise gen v *. 2.0) -. 1.0 +. offset in
  let p = point a in
  let signal = ref (increment p) in
  let v = ref (Vec.scale lacunarity p) in
  let step = Float.pow lacunarity (-.h) in
  let ea = ref step in
  let i = ref 1 in
  while float !i < octaves do
    let inc = ref (increment !v *. !ea) in
    for _ = c_int a.(7) downto 1 do
      inc := !inc *. !signal
    done;
    signal := !signal +. !inc;
    v := Vec.scale lacunarity !v;
    ea := !ea *. step;
    incr i
  done;
  let rem = octaves -. float (c_int octaves) in
  if rem <> 0.0 then !signal +. (rem *. (increment !v *. !ea) *. !signal) else !signal

(* ---------------------------------------------------------------------------------------------- *)
(* f_ridge: parameters lambda, octaves, omega, offset, ridge, generator *)

let ridge a =
  let p = point a in
  let lambda = a.(3) and omega = a.(5) and off = a.(6) and ridge = a.(7) in
  let gen = generator a.(8) in
  let octaves = c_int a.(4) in
  let rscale = 1.0 /. fmax ridge (1.0 -. ridge) and scale = 1.0 /. fmax off (1.0 -. off) in
  let resid = a.(4) -. float octaves in
  let folded v = Float.abs (Noise.noise gen v -. ridge) *. rscale in
  let value = ref (folded p -. off) and tot = ref 1.0 in
  let l = ref lambda and o = ref omega in
  for _ = 2 to octaves do
    value := !value +. (!o *. (folded (Vec.scale !l p) -. off));
    tot := !tot +. !o;
    l := !l *. lambda;
    o := !o *. omega
  done;
  if 0.0 <> resid then begin
    value := !value +. (!o *. (folded (Vec.scale !l p) -. off) *. resid);
    tot := !tot +. (!o *. resid)
  end;
  !value *. scale /. !tot

(* ---------------------------------------------------------------------------------------------- *)
(* f_ridged_mf: parameters H, lacunarity, octaves, offset, gain, generator. POV-Ray computes the
   octaves' weights lacunarity^(−i·H), i = 0 … octaves, at the declaration's first call and keeps
   them in the function's private data: later calls use them whatever their own H, lacunarity and
   octaves. A later call with more octaves reads past POV-Ray's array (undefined); here the
   sequence is continued with the first call's H and lacunarity. *)

type weights = { mutable ea : float array; h : float; lacunarity : float; mutable freq : float }

(* the weights of octaves 0 … the first i with i > octaves (C's loop i <= octaves) *)
let first_weights h lacunarity octaves =
  let w = { ea = [||]; h; lacunarity; freq = 1.0 } in
  let l = ref [] and i = ref 0 in
  while float !i <= octaves do
    l := Float.pow w.freq (-.h) :: !l;
    w.freq <- w.freq *. lacunarity;
    incr i
  done;
  w.ea <- Array.of_list (List.rev !l);
  w

let rec weight w i =
  if i < Array.length w.ea then w.ea.(i)
  else begin
    w.ea <- Array.append w.ea [| Float.pow w.freq (-.w.h) |];
    w.freq <- w.freq *. w.lacunarity;
    weight w i
  end

(* offset − |2·noise − 1|, squared *)
let[@inline] ridged gen offset v =
  let s = (Noise.noise gen v *. 2.0) -. 1.0 in
  let s = if s < 0.0 then -.s else s in
  let s = offset -. s in
  s *. s

let ridged_mf () =
  let state = ref None in
  fun a ->
    let octaves = a.(5) and lacunarity = a.(4) and offset = a.(6) and gain = a.(7) in
    let w =
      match !state with
      | Some w -> w
      | None ->
          let w = first_weights a.(3) lacunarity octaves in
          state := Some w;
          w
    in
    let gen = generator a.(8) in
    let v = ref (point a) in
    let signal = ref (ridged gen offset !v) in
    let result = ref !signal in
    let i = ref 1 in
    while float !i < octaves do
      v := Vec.scale lacunarity !v;
      let weight_i = !signal *. gain in
      let weight_i = if weight_i > 1.0 then 1.0 else weight_i in
      let weight_i = if weight_i < 0.0 then 0.0 else weight_i in
      signal := ridged gen offset !v *. weight_i;
      result := !result +. (!signal *. weight w !i);
      incr i
    done;
    !result

(* ---------------------------------------------------------------------------------------------- *)

let noise3d gen a = Noise.noise gen (point a)
let noise_generator a = Noise.noise (generator a.(3)) (point a)

let make ~noise_generator:gen k =
  match k with
  | 29 -> Some hetero_mf
  | 58 -> Some ridge
  | 59 -> Some (ridged_mf ())
  | 76 -> Some (noise3d gen)
  | 78 -> Some noise_generator
  | _ -> None
