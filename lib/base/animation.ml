(* Animations as POV-Ray's front end runs them (vfe.cpp, animationprocessing.cpp). *)

type values = {
  clock_on : bool;
  clock_delta : float;
  frame_number : int;
  initial_frame : int;
  final_frame : int;
  initial_clock : float;
  final_clock : float;
}

let f32 = Precision.f32

let still ~clock_on =
  { clock_on; clock_delta = 0.; frame_number = 0; initial_frame = 0; final_frame = 0; initial_clock = 0.; final_clock = 0. }

type settings = {
  initial_frame : int option;
  final_frame : int option;
  initial_clock : float option;
  final_clock : float option;
  cyclic : bool;
  subset_start : float option;
  subset_end : float option;
  frame_step : int option;
}

let no_settings =
  { initial_frame = None; final_frame = None; initial_clock = None; final_clock = None; cyclic = false; subset_start = None;
    subset_end = None; frame_step = None }

type frame = { clock : float; values : values }

type plan = { frames : frame Seq.t; count : int; digits : int }

(* a value as the front end declares it to the scene: written with six significant digits and
   read back (clock_delta 1.6/7 is 0.228571) *)
let declared x = float_of_string (Printf.sprintf "%g" x)

(* a subset bound: 0 or at least 1 is a frame number, a fraction between is a share of the frames *)
let subset_bound v ~initial ~final =
  let v = Float.max (f32 v) 0. in
  if v = 0. || v >= 1. then int_of_float v else int_of_float (f32 (float_of_int (final - initial + 1) *. v))

let plan (s : settings) =
  (* vfe renders a still when neither frame is given or both are 1 (or 0) *)
  match (Option.value s.initial_frame ~default:0, Option.value s.final_frame ~default:0) with
  | (0, 0) | (1, 1) -> None
  | _ ->
      let initial = max (Option.value s.initial_frame ~default:1) 0 in
      let initial_clock = f32 (Option.value s.initial_clock ~default:0.) in
      let final = max (Option.value s.final_frame ~default:1) initial in
      let final_clock = f32 (Option.value s.final_clock ~default:1.) in
      let step = max (Option.value s.frame_step ~default:1) 1 in
      let final = if s.cyclic then final + 1 else final in
      let first = match s.subset_start with Some v -> max (subset_bound v ~initial ~final) initial | None -> initial in
      let last =
        match s.subset_end with
        | Some v -> max (subset_bound v ~initial ~final) first
        | None -> if s.cyclic then final - 1 else final
      in
      (* the clocks' difference in single precision, divided in double *)
      let delta = f32 (final_clock -. initial_clock) /. float_of_int (final - initial) in
      let frame n =
        let clock = f32 ((delta *. float_of_int (n - initial)) +. initial_clock) in
        { clock;
          values =
            { clock_on = true; clock_delta = declared delta; frame_number = n; initial_frame = initial; final_frame = final;
              initial_clock = declared initial_clock; final_clock = declared final_clock } }
      in
      (* the first frame always; then while the next one is within the subset. The frames are
         made one at a time as they are rendered: an animation of two billion frames is a long
         render, not a list of two billion frames. *)
      let count = 1 + ((max 0 (last - first)) / step) in
      let rec from k () = if k >= count then Seq.Nil else Seq.Cons (frame (first + (k * step)), from (k + 1)) in
      let frames = from 0 in
      let digits = String.length (string_of_int final) in
      Some { frames; count; digits }

let numbered base ~frame ~digits =
  let n = string_of_int frame in
  base ^ String.make (max 0 (digits - String.length n)) '0' ^ n
