(* Difference heat maps of two images. *)

(* The ramp's stops: blue, magenta, red, yellow; all bright, so even a 1/255 difference stands out
   against the dark grey of the equal pixels. *)
let stops = [| (40, 90, 255); (200, 40, 220); (255, 40, 40); (255, 240, 60) |]

let colour ~peak d =
  let peak = max 1 peak in
  let d = max 1 (min peak d) in
  let t = if peak = 1 then 1. else float_of_int (d - 1) /. float_of_int (peak - 1) in
  let n = Array.length stops - 1 in
  let s = t *. float_of_int n in
  let i = min (n - 1) (int_of_float s) in
  let f = s -. float_of_int i in
  let (r0, g0, b0), (r1, g1, b1) = (stops.(i), stops.(i + 1)) in
  let mix a b = int_of_float (Float.round (float_of_int a +. (f *. float_of_int (b - a)))) in
  (mix r0 r1, mix g0 g1, mix b0 b1)

let image (a : Encode.t) (b : Encode.t) =
  if a.width <> b.width || a.height <> b.height then
    Error (Printf.sprintf "sizes differ: %dx%d against %dx%d" a.width a.height b.width b.height)
  else
    let n = a.width * a.height in
    let at (img : Encode.t) i = Char.code (Bytes.get img.pixels i) in
    let diff p = max (abs (at a (3 * p) - at b (3 * p))) (max (abs (at a ((3 * p) + 1) - at b ((3 * p) + 1))) (abs (at a ((3 * p) + 2) - at b ((3 * p) + 2)))) in
    let peak = ref 0 in
    for p = 0 to n - 1 do
      peak := max !peak (diff p)
    done;
    let out = Bytes.create (3 * n) in
    for p = 0 to n - 1 do
      let r, g, bl =
        match diff p with
        | 0 ->
            let l = ((299 * at a (3 * p)) + (587 * at a ((3 * p) + 1)) + (114 * at a ((3 * p) + 2))) / 1000 in
            let v = l / 4 in
            (v, v, v)
        | d -> colour ~peak:!peak d
      in
      Bytes.set out (3 * p) (Char.chr r);
      Bytes.set out ((3 * p) + 1) (Char.chr g);
      Bytes.set out ((3 * p) + 2) (Char.chr bl)
    done;
    Ok { Encode.width = a.width; height = a.height; pixels = out }
