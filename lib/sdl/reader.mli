(** The reader of the scene language: the parser state, the token stream with its frames (scene
    file, included files, macro bodies), the symbol tables, and the helpers every part of the
    interpreter uses to look at tokens and report errors (docs/povray-rules.md §11). *)

module V = Value

(** Hash tables keyed by names, compared with [String.equal]. *)
module Names : Hashtbl.S with type key = string

(** What the scene can see of the command line (see [Interp.options]). *)
type options = {
  width : int;
  height : int;
  clock : float;
  animation : Animation.values;
  declares : (string * V.t) list;
  library_paths : string list;
  debug : string -> unit;
  included : string -> depth:int -> float -> unit;
  limits : Scene_limits.t;
  access : Access.t;
}

(** The camera as written. *)
type camera_spec = V.camera_spec = {
  c_location : Vec.t option;
  c_direction : Vec.t option;
  c_up : Vec.t option;
  c_right : Vec.t option;
  c_sky : Vec.t option;
  c_look_at : (Vec.t * Loc.t) option;
  c_angle : (float * Loc.t) option;
  c_trans : Transform.t option;
  c_ortho : bool;
}

(** A feature povml does not render yet: where, what, and notes. *)
exception Unsupported of Loc.t * string * (Loc.t * string) list

(** Where tokens come from, with the conditionals and loops open in it. *)
type frame = { lx : Lexer.t; kind : frame_kind; mutable conds : cond list }

and frame_kind =
  | Main
  | Included of Loc.t * float  (** where the #include was, and when reading it began *)
  | Macro_body of string * Loc.t  (** the macro and where it was called *)

(** An open conditional or loop. *)
and cond =
  | If_branch of Loc.t
  | While_loop of Lexer.mark * Loc.t
  | For_loop of { var : V.t ref; stop : float; step : float; body : Lexer.mark; floc : Loc.t }
  | Switch_case of { value : float; mutable running : bool; sloc : Loc.t }

(** [global_settings { charset … }] (§15.9): ascii (the default), utf8 or sys. *)
type charset = Ascii | Utf8 | Sys

(** The state of one interpretation. *)
type st = {
  mutable frames : frame list;
  mutable cur : Token.t;
  mutable have : bool;
  mutable cur_elem : (V.array_v * int) option;
  mutable no_expand : bool;
  mutable defer : bool;
  mutable in_rvalue : bool;  (** reading a declaration's value *)
  mutable pending_macro : (V.macro * Loc.t) option;
      (** a macro named just past a declaration's value, called when the next token is asked for *)
  mutable streams : V.stream array;
  mutable depth : int;  (** '{' minus '}' consumed *)
  mutable parens : int;  (** '(' minus ')' consumed *)
  opts : options;
  global : V.t ref Names.t;
  mutable tables : V.t ref Names.t list;
  mutable includes : int;
  mutable macro_depth : int;
  mutable macro_calls : int;  (** macro calls so far, against [opts.limits] *)
  mutable iterations : int;  (** loop iterations so far, all loops together *)
  mutable string_bytes : int;  (** the bytes of the strings the string functions built so far *)
  mutable nesting : int;  (** parentheses, vectors, signs and unions open in the reader *)
  mutable braces : int;  (** POV-Ray's count of nested blocks, for its warning past 200 *)
  mutable object_count : int;  (** objects and lights that entered the scene *)
  mutable isosurfaces : int;  (** isosurfaces read: the next one's number ({!Isosurface.t}'s key) *)
  mutable split_unions : int;  (** unions split so far: each its members' shared interior's number *)
  probe_work : Scratch.t Lazy.t;
      (** the scratch of the parse-time trace() calls, made by the first and renewed for each:
          POV-Ray's parser has one thread's data, whose isosurfaces' state and height fields'
          vertex normals carry from call to call *)
  mutable probed : (V.obj * Compiled.t) option;  (** the object trace(), inside() or an extent function compiled last, and its compiled scene *)
  mutable version : int;
  mutable version_set : bool;
  mutable charset : charset;  (** [global_settings { charset … }]: how a text's string is read (§15.9) *)
  mutable warnings : Error.t list;
  mutable objects : Scene.obj list;
  mutable lights : Scene.light list;
  mutable camera : camera_spec option;
  mutable background : Colour.t option;
  mutable sky : Scene.sky option;
  mutable assumed_gamma : float option;
  mutable max_trace_level : int;
  mutable adc_bailout : float;
  mutable noise_generator : int;  (** global_settings: 1, 2 (default) or 3 *)
  mutable irid_wavelength : Rgb.t;  (** global_settings: the wavelengths iridescence uses *)
  mutable number_of_waves : int;  (** global_settings: the wave sources of waves and ripples, 10 by default *)
  mutable ambient_light : Rgb.t;
  mutable default_texture : Scene.layer;
  mutable directive : st -> string -> Loc.t -> unit;
  mutable invoke : st -> V.macro -> Loc.t -> unit;
  mutable index : st -> V.array_v -> int;
  mutable files : V.user_file list;
  mutable read_object : st -> V.obj option;
      (** the object parser (Objects), for the object pattern inside a pigment or normal, which
          Materials reads but cannot name (Objects uses Materials): the object written next,
          else None *)
  mutable read_pigment : st -> Scene.pigment;
      (** reads a pigment block after its keyword, from a black pigment (POV-Ray's Create_Pigment): Materials' reader, for [pigment_pattern] *)
  mutable read_special_function : st -> string -> Loc.t -> Fn.t option;
      (** reads the function a keyword starts inside [function { … }] ([pigment], [transform],
          [spline], [pattern]; None for another): Declare's reader, for the function images that
          Image_reader reads but cannot name (Declare uses the image readers) *)
}

val keywords : string list
(** [keywords] are the keywords povml reads. *)

val unsupported : string list
(** [unsupported] are POV-Ray keywords povml reports as "not supported yet". *)

val reserved : string list
(** [reserved] are POV-Ray's other reserved words, which povml does not read: keywords that cannot
    be declared, reported as out of place where they are met. *)

val set_of : string list -> unit Names.t
(** [set_of l] is the set of the names in [l]. *)

val is_keyword : string -> bool
(** [is_keyword s] tells whether [s] is a keyword (read, not yet supported, or reserved). *)

val is_unsupported : string -> bool
(** [is_unsupported s] tells whether [s] is a keyword povml does not read yet. *)

val top : st -> frame
(** [top st] is the frame tokens are read from. *)

val commas : int -> string
(** [commas n] is [n] with thousands separated by commas ("10,000,000"), as limits are printed. *)

val check_memory : st -> Loc.t -> unit
(** [check_memory st loc] raises a [Limit] error at [loc] when the heap has reached the memory limit. *)

val count_iteration : st -> Loc.t -> unit
(** [count_iteration st loc] counts one loop iteration of the loop at [loc], raising a [Limit] error
    past the limit (or past the memory limit). *)

val with_function_steps : st -> Loc.t -> (unit -> 'a) -> 'a
(** [with_function_steps st loc f] is [f ()], calls of user functions from the scene language;
    when their steps run out ([Fn_budget.Exhausted]), a [Limit] error at [loc] naming
    [--max-function-steps]. *)

val count_string : st -> Loc.t -> int -> unit
(** [count_string st loc n] counts a string of [n] bytes built by a string function, raising a
    [Limit] error at [loc] past the limit on all strings built together. *)

val count_object : st -> Loc.t -> unit
(** [count_object st loc] counts one object or light entering the scene, raising a [Limit] error
    past the limit. *)

val nest : st -> Loc.t -> (unit -> 'a) -> 'a
(** [nest st loc f] is [f ()] read one nesting level deeper, raising a [Limit] error at [loc]
    when that is deeper than the limit (the reader recurses on nesting: this keeps the stack safe). *)

val lookup_cell : st -> string -> V.t ref option
(** [lookup_cell st name] is the cell of [name] in the innermost table that has it. *)

val lookup : st -> string -> V.t option
(** [lookup st name] is the value of [name], innermost table first. *)

val fill : st -> unit
(** [fill st] reads the next token into [st.cur], running directives and calling macros on the way. *)

val peek : st -> Token.kind
(** [peek st] is the next token, read if needed (pending directives run first). *)

val peek_follow : st -> Token.kind
(** [peek_follow st] is the token after a complete value; a directive there waits until the value is used. *)

val peek_past : st -> Token.kind
(** [peek_past st] is [peek st] after a complete value: an [Unsupported] raised by the directives and
    macro calls read there is raised as the located error [Error.Scene_error]. *)

val cur_value : st -> string -> V.t option
(** [cur_value st name] is the value of the current identifier token (an array element if subscripted). *)

val peek_loc : st -> Loc.t
(** [peek_loc st] is the location of the next token. *)

val advance : st -> unit
(** [advance st] consumes the current token. *)

val warn : st -> Loc.t -> ('a, unit, string, unit) format4 -> 'a
(** [warn st loc fmt …] records a warning at [loc]. *)

val unsupported_error : Loc.t -> string -> (Loc.t * string) list -> exn
(** [unsupported_error loc what notes] is the error "not supported yet: [what]" at [loc]. *)

val not_supported : Loc.t -> string -> 'a
(** [not_supported loc what] raises [Unsupported] for [what] at [loc]. *)

val unsupported_use : Loc.t -> string -> string -> Loc.t -> 'a
(** [unsupported_use loc name what at] raises [Unsupported] for using [name], declared at [at] with [what]. *)

val unknown_identifier : st -> Loc.t -> string -> 'a
(** [unknown_identifier st loc name] raises "unknown identifier" with the nearest names. *)

val unexpected : st -> string -> 'a
(** [unexpected st what] raises "expected [what] but found …" at the next token. *)

val expect : st -> Token.kind -> string -> unit
(** [expect st k what] consumes [k] or raises [unexpected]. *)

val open_block : st -> string -> unit
(** [open_block st what] consumes the '{' after [what]. *)

val read_items : int -> (int -> 'a) -> 'a array
(** [read_items n item] is [[| item 0; …; item (n − 1) |]], the calls made in order, for a list
    whose length the scene gives: the array is made from what was read, so a huge count fails at
    the first item that is not there instead of allocating an array of that size. *)

exception Object_copy of V.obj * string
(** Raised by {!open_shape} with the object named and the shape's keyword. *)

val open_shape : st -> string -> unit
(** [open_shape st kw] is [open_block st kw] for the shape [kw], which then raises {!Object_copy}
    when an object identifier follows the '{' (consumed): POV-Ray's Parse_Object_Id makes the
    shape a copy of that object, whatever its kind, with the modifiers that follow, as [object]
    does. The object parser catches it. *)

val close_block : st -> string -> unit
(** [close_block st what] consumes the '}' closing [what]. *)

val accept : st -> Token.kind -> bool
(** [accept st k] consumes [k] if it comes next. *)

val skip_comma : st -> unit
(** [skip_comma st] consumes a ',' if one comes next (where the comma between arguments is optional). *)

val is_ident : st -> string -> bool
(** [is_ident st s] tells whether the next token is the identifier [s]. *)

val accept_ident : st -> string -> bool
(** [accept_ident st s] consumes the identifier [s] if it comes next. *)

val peek_name : st -> Token.kind
(** [peek_name st] is the next token where a name is expected: a macro name there is not called. *)

val main_file : st -> string
(** [main_file st] is the scene file's name. *)

val include_dirs : st -> string list
(** [include_dirs st] are the directories searched for include files, in order. *)

val find_file : ?inc:bool -> st -> string -> string option
(** [find_file ?inc st name] is the include file [name] ([name.inc] too unless [~inc:false]). *)

val read_file : string -> string
(** [read_file path] is the text of [path]; a located error if it cannot be read. *)
