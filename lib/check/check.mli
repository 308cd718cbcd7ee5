(** [povml check]: one scene rendered by povml and by POV-Ray with the same switches, compared. *)

type thresholds = {
  max_differing : float option;  (** largest allowed share of differing pixels, 0 … 1 *)
  max_peak : int option;  (** largest allowed channel difference, 1/255 units *)
  min_psnr : float option;  (** smallest allowed PSNR, dB *)
}

type config = {
  povml : string;  (** povml's executable *)
  povray : string;  (** POV-Ray's executable *)
  scene : string;
  output : string option;  (** povml's image (+O); default the scene's name with .png, beside it *)
  switches : string list;  (** the user's switches, given to both renderers *)
  runs : int;  (** timed runs per renderer, alternating *)
  thresholds : thresholds;
}

type outcome = {
  switches : string list;  (** the switches as shown: the user's with the default size and threads *)
  povml_times : float list;  (** wall seconds of each run *)
  povray_times : float list;
  cmp : Compare.t;
  povml_png : string;  (** where povml's image was written *)
  povray_png : string;  (** POV-Ray's image, beside povml's, named [<base>-povray.png] *)
  diff_png : string;  (** the heat map, beside povml's image, named [<base>-diff.png] *)
  violations : string list;  (** one sentence per threshold exceeded *)
}

val paths : scene:string -> output:string option -> string * string * string
(** [paths ~scene ~output] is where povml's image, POV-Ray's image and the heat map go. *)

val violations : thresholds -> Compare.t -> string list
(** [violations t cmp] says, one sentence each, which thresholds of [t] the comparison [cmp] exceeds. *)

type failure =
  | Render_failed of string  (** a renderer failed, or the images cannot be compared *)
  | Cannot_write of string  (** an image cannot be written *)

val run : config -> (outcome, failure) result
(** [run config] renders with both renderers in a private directory, compares, writes the three
    images and checks the thresholds. *)

val summary : outcome -> string
(** [summary o] is the text [povml check] prints: both times and their ratio, the differing pixels,
    peak, RMSE and PSNR, the images written, and PASS or FAIL with the reasons. *)
