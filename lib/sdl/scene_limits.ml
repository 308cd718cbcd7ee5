type t = {
  include_depth : int;
  macro_depth : int;
  macro_calls : int;
  iterations : int;
  objects : int;
  nesting : int;
  memory_mb : int;
  pixels : int;
}

let default =
  {
    include_depth = 64;
    macro_depth = 10_000;
    macro_calls = 10_000_000;
    iterations = 10_000_000;
    objects = 10_000_000;
    nesting = 10_000;
    memory_mb = 4096;
    pixels = 8192 * 8192;
  }
