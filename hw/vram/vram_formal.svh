// Formal properties of vram, included into it under `ifdef FORMAL_VRAM (tools/girtd
// formal proves them on the reduced instance hw/formal.json names: a screen
// and pages small enough for the clear's loop over every word to be unrolled;
// nothing here depends on the sizes but the loop bounds and the address split).
// Labelled asserts are the properties; the comment after each is its table row.
// The environment: reset first; one base tick per edge (ticks_i = 1, as in
// hardware: the tick warp is a simulation shortcut, checked by regression
// against stepping); the timing registers fixed; no page request on the tick
// a clear is asked for (the contract the simulation check above flags); from
// the tick a clear is asked for until it is done, no swap (the VRAM fixes the
// buffer when the clear starts) and the background held (the harness clears
// with the back end idle, before the frame's first triangle).
// The checker keeps its own front buffer, operation and clear, from the
// ports: which buffer a write or a clear lands in is not taken from the VRAM.
logic f_past_q = 1'b0;
always_ff @(posedge clk_i) f_past_q <= 1'b1;
logic [girtd_pkg::TIME_W-1:0] f_cycle_q;
logic [LT-1:0] f_clear_ticks_q, f_steal_q;
always_ff @(posedge clk_i) {f_cycle_q, f_clear_ticks_q, f_steal_q} <= {cycle_ticks_i, clear_ticks_i, steal_period_ticks_i};
always_comb begin
  if (!f_past_q) assume (!rst_ni);
  assume (ticks_i == LT'(1));
  if (f_past_q) assume ({cycle_ticks_i, clear_ticks_i, steal_period_ticks_i} == {f_cycle_q, f_clear_ticks_q, f_steal_q});
  assume (!(clear_i && (req_i || swap_i)));
  if (f_clearing_q) assume (!swap_i && !clear_i && background_i == f_clear_bg_q);
end

// One word, chosen by the solver, followed apart from the array: each of its
// fields as last written (by a page write or a clear), once known.
(* anyconst *) logic [girtd_pkg::PAGE_NUMBER_W-1:0] f_page;
(* anyconst *) logic [IW-1:0] f_index;
function automatic logic [CW-1:0] f_cell_of(input logic [PW-1:0] data);  // constant part selects
  f_cell_of = '0;
  for (int i = 0; i < N; i++) if (f_index == IW'(i)) f_cell_of = data[i*CW+:CW];
endfunction
// The ports' view: the buffer shown, a page operation taken (on the back
// buffer of that tick), a clear asked for (of the back buffer and background
// of that tick) until the VRAM is done with it.
logic f_front_q, f_take, f_op_we_q, f_op_buf_q, f_clearing_q, f_clear_buf_q;
logic [girtd_pkg::PAGE_NUMBER_W-1:0] f_op_page_q;
logic [PW-1:0] f_op_data_q;
logic [RGB-1:0] f_clear_bg_q;
assign f_take = req_i && !busy_o && !clear_i;
logic f_clear_ends;  // the clear's last tick (when the VRAM writes the array)
assign f_clear_ends = f_clearing_q && finishing && clearing_q;
always_ff @(posedge clk_i) begin
  if (!rst_ni) {f_front_q, f_clearing_q} <= '0;
  else begin
    if (swap_i) f_front_q <= !f_front_q;
    if (clear_i) {f_clearing_q, f_clear_buf_q, f_clear_bg_q} <= {1'b1, !f_front_q, background_i};
    else if (f_clear_ends) f_clearing_q <= 1'b0;
  end
  if (f_take) {f_op_we_q, f_op_buf_q, f_op_page_q, f_op_data_q} <= {we_i, !f_front_q, page_i, wdata_i};
end

// One word, chosen by the solver, followed apart from the array: each of its
// fields as last written (by a page write or a clear), once known.
logic [RGB-1:0] f_rgb_q[2], f_rgb_d[2];
logic [ZO-1:0] f_z_q, f_z_d;
logic [1:0] f_rgb_known_q, f_rgb_known_d;
logic f_z_known_q, f_z_known_d;
logic [CW-1:0] f_written;
assign f_written = f_cell_of(f_op_data_q);
always_comb begin  // the word after this tick's write, if any
  {f_rgb_d[0], f_rgb_d[1], f_z_d, f_rgb_known_d, f_z_known_d} = {f_rgb_q[0], f_rgb_q[1], f_z_q, f_rgb_known_q, f_z_known_q};
  if (rst_ni && f_clear_ends) begin
    f_rgb_d[f_clear_buf_q] = f_clear_bg_q;
    f_rgb_known_d[f_clear_buf_q] = 1'b1;
    f_z_d = Z_CLEAR;
    f_z_known_d = 1'b1;
  end else if (rst_ni && done_o && f_op_we_q && f_op_page_q == f_page) begin
    f_rgb_d[f_op_buf_q] = f_written[ZO+:RGB];
    f_rgb_known_d[f_op_buf_q] = 1'b1;
    f_z_d = f_written[ZO-1:0];
    f_z_known_d = 1'b1;
  end
end
always_ff @(posedge clk_i) begin
  {f_rgb_q[0], f_rgb_q[1], f_z_q} <= {f_rgb_d[0], f_rgb_d[1], f_z_d};
  {f_rgb_known_q, f_z_known_q} <= !f_past_q ? '0 : {f_rgb_known_d, f_z_known_d};
end

// A fetch of the word's page: what it must return (the back buffer and Z as
// they are once this tick's write is done), checked when the fetch ends.
logic f_reading_q, f_expect_rgb_known_q, f_expect_z_known_q, f_cleared_q;
logic [RGB-1:0] f_expect_rgb_q;
logic [ZO-1:0] f_expect_z_q;
logic [1:0] f_ops_q;  // page operations taken and not yet done
always_ff @(posedge clk_i) begin
  if (!rst_ni) begin
    f_reading_q <= 1'b0;
    f_ops_q <= '0;
    f_cleared_q <= 1'b0;
  end else begin
    if (done_o) f_reading_q <= 1'b0;
    if (f_take && !we_i && page_i == f_page) begin
      f_reading_q <= 1'b1;
      f_expect_rgb_q <= f_rgb_d[!f_front_q];
      f_expect_rgb_known_q <= f_rgb_known_d[!f_front_q];
      f_expect_z_q <= f_z_d;
      f_expect_z_known_q <= f_z_known_d;
    end
    f_ops_q <= f_ops_q + 2'(f_take) - 2'(done_o);
    f_cleared_q <= f_clear_ends;
  end
end

logic [CW-1:0] f_read;
assign f_read = f_cell_of(rdata_o);
logic [girtd_pkg::VRAM_W-1:0] f_word;
assign f_word = mem[{f_page, f_index}];
always_comb if (f_past_q && rst_ni) begin
  if (done_o && f_reading_q) begin
    vram_read_rgb: assert (!f_expect_rgb_known_q || f_read[ZO+:RGB] == f_expect_rgb_q);  // a fetch returns the back buffer's colour last written to each word
    vram_read_z: assert (!f_expect_z_known_q || f_read[ZO-1:0] == f_expect_z_q);  // a fetch returns the Z last written to each word
  end
  if (f_cleared_q)
    vram_clear: assert ((f_clear_buf_q ? f_word[B1+:RGB] : f_word[B0+:RGB]) == f_clear_bg_q && f_word[ZL+:ZO] == Z_CLEAR);  // a clear sets every word's back buffer (when it was asked for) to the background and its Z to Z_CLEAR
  vram_front: assert (front_o == f_front_q);  // the buffer shown changes exactly at each swap
  vram_take: assert (accepting == f_take);  // a page request is taken exactly when it is made while busy_o is low (and no clear is asked for)
  vram_one_at_a_time: assert (f_ops_q == 2'(busy_q && !clearing_q && !stealing_q) && (!done_o || f_ops_q == 2'd1));  // one page operation at a time, each ended by exactly one done
  vram_word: assert ((!f_rgb_known_q[0] || f_word[B0+:RGB] == f_rgb_q[0]) && (!f_rgb_known_q[1] || f_word[B1+:RGB] == f_rgb_q[1]) &&
                     (!f_z_known_q || f_word[ZL+:ZO] == f_z_q));  // the array holds each word's fields as last written
  if (f_reading_q)
    vram_fetch_held: assert (busy_q && !we_q && !clearing_q && !stealing_q && page_q == f_page &&
                             (!f_expect_rgb_known_q || f_read[ZO+:RGB] == f_expect_rgb_q) &&
                             (!f_expect_z_known_q || f_read[ZO-1:0] == f_expect_z_q));  // a fetch in flight holds its page's data
end

`ifdef FORMAL_VRAM_LIVENESS
// For had_pops and had_idle (hw/had/had_formal.svh), which count the HAD's
// own ticks, those in which the VRAM is not busy: this VRAM is busy at most
// 2 max(cycle, 1) ticks in a row (a page operation, then a stolen cycle owed
// behind it) whenever a stolen cycle comes at most once in two cycles (the
// least period the config accepts), from the first tick it is idle after
// each clear. The harness's frame start is the environment: a clear asked
// for only with the VRAM idle, and no page request until the VRAM is idle
// again (the harness waits for the back end's idle_o, which includes the
// VRAM's, so a backlog of stolen cycles owed during a long clear is worked
// off first).
logic f_op_q, f_settled_q;
logic [LT:0] f_busy_run_q, f_run_bound;
always_ff @(posedge clk_i) begin
  if (!rst_ni) f_op_q <= 1'b0;
  else if (f_take) f_op_q <= 1'b1;
  else if (done_o) f_op_q <= 1'b0;
  f_busy_run_q <= !rst_ni || !busy_o ? '0 : f_busy_run_q + (LT + 1)'(f_busy_run_q != '1);
  f_settled_q <= !rst_ni || (!clear_i && (f_settled_q || !busy_o));  // busy_o is not yet high on the clear's own tick
end
assign f_run_bound = 2 * (cycle_ticks_i == '0 ? (LT + 1)'(1) : (LT + 1)'(cycle_ticks_i));
always_comb begin
  assume (steal_period_ticks_i == '0 || (LT + 1)'(steal_period_ticks_i) >= f_run_bound);
  if (clear_i) assume (f_settled_q && !busy_o && (!f_op_q || done_o));  // the back end's idle_o may rise on a write's done tick
  if (!f_settled_q) assume (!req_i);
end
always_comb if (f_past_q && rst_ni) begin
  if (f_settled_q && busy_o) vram_busy_run: assert (f_busy_run_q < f_run_bound);  // from its first idle tick after a clear, busy at most 2 max(cycle, 1) ticks in a row (a steal at most once in two cycles)
end
`endif
