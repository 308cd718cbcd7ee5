(** How much a scene may ask for: the limits that make every scene end, with a located error of
    kind [Error.Limit], in bounded time and memory. Each has a command-line switch. *)

type t = {
  include_depth : int;  (** nested [#include] files (POV-Ray stops at 31) *)
  macro_depth : int;  (** nested macro calls (POV-Ray stops at 98) *)
  macro_calls : int;  (** macro calls in the whole scene *)
  iterations : int;  (** [#while] and [#for] iterations in the whole scene, all loops together *)
  objects : int;  (** objects and light sources in the scene (a mesh is one) *)
  nesting : int;  (** nested parentheses, braces, vectors and unions *)
  memory_mb : int;  (** the interpreter's heap, in MiB *)
  pixels : int;  (** width × height of the image *)
  pattern_steps : int;  (** the work of one pattern at one point: a fractal's iterations, the wave sources of waves and ripples *)
  function_steps : int;
      (** the operations of the user functions the scene calls while it is read, all calls together
          ({!Fn_budget}; rendering is not counted) *)
  string_mb : int;  (** the strings the string functions build, all together, in MiB *)
}

val default : t
(** [default]: include depth 64, macro depth 10,000, 3,000,000 macro calls, 10,000,000 loop
    iterations, 10,000,000 objects, nesting 10,000, memory 4,096 MiB (or half the address space
    the process may use, [ulimit -v], when that is less), 67,108,864 pixels (8192²), 100,000 pattern steps,
    1,000,000,000 function steps, 4,096 MiB of strings built. *)
