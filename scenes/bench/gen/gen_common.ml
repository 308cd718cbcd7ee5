(* What the benchmark generators share: number formatting and a seeded integer hash. *)

(* A number with at most 4 decimals and no trailing zeros ("-0" is written "0"). *)
let fmt x =
  let s = Printf.sprintf "%.4f" x in
  let i = ref (String.length s - 1) in
  while s.[!i] = '0' do decr i done;
  if s.[!i] = '.' then decr i;
  let s = String.sub s 0 (!i + 1) in
  if s = "-0" then "0" else s

(* 32-bit integer hash (lowbias32 by Chris Wellons): the same numbers on every run, no Random *)
let hash32 x =
  let m = 0xffffffff in
  let x = x land m in
  let x = x lxor (x lsr 16) in
  let x = (x * 0x7feb352d) land m in
  let x = x lxor (x lsr 15) in
  let x = (x * 0x846ca68b) land m in
  x lxor (x lsr 16)

(* The g x g grid (g = ceil (sqrt n)) of cells covering [-half, half]² for n items, and its cell side. *)
let grid n half =
  let g = int_of_float (ceil (sqrt (float_of_int n))) in
  let g = if g * g < n then g + 1 else g in
  (g, 2.0 *. half /. float_of_int g)

(* A buffered writer to [path]: the function that adds a string, and the one that finishes the file. *)
let writer path =
  let oc = open_out_bin path in
  let b = Buffer.create (1 lsl 20) in
  let flush () = Buffer.output_buffer oc b; Buffer.clear b in
  let add s = Buffer.add_string b s; if Buffer.length b > 1 lsl 20 then flush () in
  (add, fun () -> flush (); close_out oc)
