(** Animations as POV-Ray 3.7's front end runs them (vfe.cpp, animationprocessing.cpp): which
    frames, the clock of each, the identifiers a frame's scene sees, and the frames' file names. *)

(** What a scene sees of the animation besides [clock]: POV-Ray declares these identifiers for
    every render, a still's all 0. The clocks and their step are as the front end declares them:
    written with six significant digits ([%g]) and read back. *)
type values = {
  clock_on : bool;  (** a clock was given: +K, or an animation *)
  clock_delta : float;  (** the clock's step from frame to frame *)
  frame_number : int;
  initial_frame : int;
  final_frame : int;  (** one more than written for a cyclic animation *)
  initial_clock : float;
  final_clock : float;
}

val still : clock_on:bool -> values
(** [still ~clock_on] is a still's values: every number 0. *)

(** The animation options as given (+KFI, +KFF, +KI, +KF, +KC, +SF, +EF, Frame_Step). *)
type settings = {
  initial_frame : int option;
  final_frame : int option;
  initial_clock : float option;
  final_clock : float option;
  cyclic : bool;
  subset_start : float option;  (** a frame number, or a share of the frames when between 0 and 1 *)
  subset_end : float option;
  frame_step : int option;
}

val no_settings : settings
(** [no_settings] is none given: a still. *)

type frame = { clock : float; values : values }
(** One frame to render: its clock (single precision) and the scene's identifiers. *)

type plan = {
  frames : frame Seq.t;  (** the frames, in order, each made when it is reached *)
  count : int;  (** how many there are *)
  digits : int;  (** the digits of their numbers in file names (those of the final frame) *)
}
(** An animation's frames. *)

val plan : settings -> plan option
(** [plan s] is the animation [s] asks for, or None for a still: as POV-Ray's front end, neither
    frame given or both 1 (or both 0) is a still. The initial frame defaults to 1 (at least 0),
    the final to 1 (at least the initial, one more when cyclic), the clocks to 0 and 1; the clock
    steps by (final − initial clock) / (final − initial frame); the subset's first frame is always
    rendered, then every [frame_step]-th while within the subset's end (the final frame, the one
    before it when cyclic). *)

val declared : float -> float
(** [declared x] is [x] as the front end declares a value to the scene: written with six
    significant digits ([%g]) and read back (1.6/7 becomes 0.228571). *)

val numbered : string -> frame:int -> digits:int -> string
(** [numbered base ~frame ~digits] is [base] followed by [frame] padded with zeros to [digits]:
    [numbered "clockd" ~frame:3 ~digits:2] is ["clockd03"]. *)
