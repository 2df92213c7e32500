// Formal properties of the whole back end (tools/girtd formal; hw/formal.json):
// its progress. A wrapper: the properties read only girtd_backend's ports, so
// the top is proven as built, with its gated DDA clock.
//
// Clocks: the solver steps a global clock; clk toggles on every step, and
// the DDA's clock is clk gated by dda_step_o as it stood while clk was low,
// which is how the harness drives it (sim/rtl/backend_rtl_core.hpp). The
// check runs with the "multiclock" flow (yosys clk2fflogic): every flip-flop
// takes its input of the step before its clock rises.
//
// Environment, as the harness drives the back end: one reset clock first;
// the timing and options constant: the options and the FIFO's limit (1..DEPTH)
// free, each timing the value its parameter gives (in ticks; -1: free within
// its port's width and the configuration's rules, a stolen VRAM cycle every 0
// (never) or at least two VRAM cycles; dda_clocked is proven with the
// timing free, fifo_pops with it fixed: hw/README.md); one base tick per
// edge (ticks_i = 1, as in hardware);
// every parameter set within the preparer's contract (models/dda/README.md:
// the box cut to the window, Xmin <= X0 <= Xmax, Y0 <= Ymax); a clear asked
// for only while the back end is idle. hw/formal.json cuts the DDA's state
// and output and every data word the control reads (the pixels' colour, nf
// and Z, the VRAM's read data): they may be anything on every clock, so the
// bounds hold for any DDA, triangles and pictures.
module girtd_backend_formal #(
    parameter int PERIOD = -1, ACCESS = -1, BLEND = -1, CYCLE = -1, STEAL = -1, CLEAR = -1
) (
    input logic in_valid_i,
    input logic [girtd_pkg::XY_W-1:0] x0_i, y0_i, xmin_i, xmax_i, ymax_i,
    input logic q_zero_i,
    input logic signed [girtd_pkg::Q_K_W-1:0] q_k_i,
    input logic [2:0] hard_edges_i,
    input logic clamped_i,
    input logic signed [girtd_pkg::COLOR_W-1:0] r_i, r_dx_i, r_dy_i, g_i, g_dx_i, g_dy_i, b_i, b_dx_i, b_dy_i,
    input logic signed [girtd_pkg::T_W-1:0] t_i, t_dx_i, t_dy_i,
    input logic signed [girtd_pkg::Z_W-1:0] z_i, z_dx_i, z_dy_i,
    input logic signed [girtd_pkg::D_W-1:0] d1_i, d1_dx_i, d1_dy_i, d2_i, d2_dx_i, d2_dy_i, d3_i, d3_dx_i, d3_dy_i,
    input logic clear_i,
    input logic flush_i,
    input logic swap_i
);
  localparam int XY_W = girtd_pkg::XY_W, W = 1 << girtd_pkg::SCREEN_BITS;
  localparam int TW = girtd_pkg::TIME_W, LT = girtd_pkg::LONG_TIME_W, CW = girtd_pkg::FIFO_COUNT_W;

  logic f_clk = 1'b0, f_gate_q = 1'b0, dda_step;
  always @($global_clock) begin
    f_clk <= !f_clk;
    f_gate_q <= dda_step;
  end
  logic dda_clk;
  assign dda_clk = f_clk && f_gate_q;
  logic rst_n = 1'b0;  // low for the first clock only
  always_ff @(posedge f_clk) rst_n <= 1'b1;

  (* anyconst *) logic [girtd_pkg::DDA_PERIOD_W-1:0] f_period;
  (* anyconst *) logic [TW-1:0] f_access, f_blend, f_cycle;
  (* anyconst *) logic [LT-1:0] f_clear, f_steal;
  (* anyconst *) logic [CW-1:0] f_limit;
  (* anyconst *) logic [5:0] f_options;
  (* anyconst *) logic [3*girtd_pkg::COLOR_OUT-1:0] f_background;

  logic idle, push;
  logic [CW-1:0] fifo_count;
  girtd_backend u_be (
      .clk_i(f_clk), .rst_ni(rst_n), .dda_clk_i(dda_clk), .dda_step_o(dda_step),
      .dda_period_ticks_i(f_period), .had_access_ticks_i(f_access), .had_blend_ticks_i(f_blend),
      .vram_cycle_ticks_i(f_cycle), .clear_ticks_i(f_clear), .vram_steal_period_ticks_i(f_steal),
      .fifo_limit_i(f_limit), .write_behind_i(f_options[0]), .prefetch_i(f_options[1]), .dirty_bits_i(f_options[2]),
      .one_minus_exact_i(f_options[3]), .walk_fix_i(f_options[4]), .pipelined_compare_i(f_options[5]),
      .in_valid_i, .in_ready_o(), .x0_i, .y0_i, .xmin_i, .xmax_i, .ymax_i, .q_zero_i, .q_k_i, .hard_edges_i,
      .clamped_i, .r_i, .r_dx_i, .r_dy_i, .g_i, .g_dx_i, .g_dy_i, .b_i, .b_dx_i, .b_dy_i, .t_i, .t_dx_i, .t_dy_i,
      .z_i, .z_dx_i, .z_dy_i, .d1_i, .d1_dx_i, .d1_dy_i, .d2_i, .d2_dx_i, .d2_dy_i, .d3_i, .d3_dx_i, .d3_dy_i,
      .clear_i, .background_i(f_background), .flush_i, .swap_i, .idle_o(idle), .front_o(),
      .dda_state_o(), .dda_active_o(), .pixel_push_o(push), .pixel_x_o(), .pixel_y_o(),
      .ticks_i(LT'(1)), .quiet_o(), .dda_clocks_o(), .dda_wait_ticks_o(), .pixels_generated_o(), .written_o(),
      .blended_o(), .z_rejected_o(), .dropped_o(), .page_misses_o(), .had_busy_ticks_o(), .had_vram_wait_ticks_o(),
      .fifo_max_o(), .fifo_count_o(fifo_count), .wraps_o(), .clips_o(), .triangles_affected_o(), .first_affected_o());

  function automatic logic f_on_screen(input logic [XY_W-1:0] v);
    f_on_screen = 32'(v) < W;
  endfunction
  always_comb begin
    assume (f_limit != '0 && 32'(f_limit) <= girtd_pkg::FIFO_MAX_DEPTH);
    assume (f_steal == '0 || 32'(f_steal) >= 2 * (f_cycle == '0 ? 1 : 32'(f_cycle)));
    if (in_valid_i) assume (f_on_screen(xmin_i) && f_on_screen(xmax_i) && f_on_screen(ymax_i) &&
                            xmin_i <= x0_i && x0_i <= xmax_i && y0_i <= ymax_i);
    if (clear_i) assume (idle);
    if (PERIOD >= 0) assume (32'(f_period) == PERIOD);
    if (ACCESS >= 0) assume (32'(f_access) == ACCESS);
    if (BLEND >= 0) assume (32'(f_blend) == BLEND);
    if (CYCLE >= 0) assume (32'(f_cycle) == CYCLE);
    if (STEAL >= 0) assume (32'(f_steal) == STEAL);
    if (CLEAR >= 0) assume (32'(f_clear) == CLEAR);
  end

  // No deadlock on the way out of the DDA, in two properties of short reach:
  // - dda_clocked, at any timing: the DDA is clocked (dda_step_o) within a
  //   DDA period of ticks in which the FIFO has room, whatever its state.
  //   Inside the back end every clock of the DDA's gated clock is one it
  //   acts on (its enable and ready tied high);
  // - fifo_fills_on_clocks, at any timing: the FIFO's count grows only on
  //   a tick the DDA is clocked, so once it has room it keeps it until the
  //   next clock;
  // - fifo_pops, at the timing hw/formal.json fixes: while the FIFO holds a
  //   pixel, one leaves within f_pop_bound ticks (the pixel in the HAD
  //   finished, then the head's page fetched: an access, a blend, a
  //   write-back and a fetch, each VRAM cycle maybe behind a stolen one).
  //   At any timing the HAD's had_pops and the VRAM's vram_busy_run give
  //   the same (hw/README.md); this one checks the back end's own wiring
  //   between the FIFO and the HAD.
  // With dda_idle (hw/dda/dda_formal.sv, the DDA alone: idle, its output
  // empty, within W (W + 4) + 1 + OUT_LATENCY acting clocks of the last
  // parameter set), the DDA is idle within that many (DDA period + pop
  // bound) ticks of the last input, and the FIFO empty at most its limit of
  // pop bounds later (hw/README.md, "No deadlock").
  localparam int F_TMAX = (1 << TW) - 1, F_LMAX = (1 << LT) - 1;
  localparam int F_BOUND_MAX = (1 << girtd_pkg::DDA_PERIOD_W) + 2 * (8 * F_TMAX + 4) + F_LMAX + 4;
  localparam int F_BOUND_W = $clog2(F_BOUND_MAX + 2);
  logic [F_BOUND_W-1:0] f_period_ticks, f_cycle_ticks, f_pixel_ticks, f_pop_bound;
  assign f_period_ticks = f_period == '0 ? F_BOUND_W'(1) : F_BOUND_W'(f_period);
  assign f_cycle_ticks = f_cycle == '0 ? F_BOUND_W'(1) : F_BOUND_W'(f_cycle);
  assign f_pixel_ticks = F_BOUND_W'(f_access) + F_BOUND_W'(f_blend) + 6 * f_cycle_ticks + F_BOUND_W'(4);
  assign f_pop_bound = 2 * f_pixel_ticks + F_BOUND_W'(f_clear) + F_BOUND_W'(4);

  // A pop, seen at the ports: the count is not what it was plus a push.
  logic [CW-1:0] f_count_q;
  logic f_push_q, f_counted_q = 1'b0, f_popped;
  always_ff @(posedge f_clk) {f_count_q, f_push_q, f_counted_q} <= {fifo_count, push, rst_n};
  assign f_popped = f_counted_q && (CW + 1)'(fifo_count) != (CW + 1)'(f_count_q) + (CW + 1)'(f_push_q);

  // Ticks the FIFO has held a pixel without a pop.
  logic [F_BOUND_W-1:0] f_unpopped_q;
  always_ff @(posedge f_clk)
    f_unpopped_q <= !rst_n || fifo_count == '0 || f_popped ? '0 : f_unpopped_q + F_BOUND_W'(f_unpopped_q != '1);
  always_comb if (rst_n) begin
    fifo_pops: assert (f_unpopped_q < f_pop_bound);  // a pixel in the FIFO: one leaves within the HAD's time for two pixels, at one timing (hw/README.md)
  end

`ifdef FORMAL_BACKEND_ANY_TIMING
  // Ticks since the DDA was last clocked in which the FIFO had room. (Kept
  // out of fifo_pops' check: with this counter in its model, PDR took 574 s
  // on it instead of 14.)
  logic [F_BOUND_W-1:0] f_unclocked_q;
  logic f_step_q;
  always_ff @(posedge f_clk) begin
    f_unclocked_q <= !rst_n || dda_step ? '0 : f_unclocked_q + F_BOUND_W'(fifo_count < f_limit && f_unclocked_q != '1);
    f_step_q <= dda_step;
  end
  always_comb if (rst_n) begin
    dda_clocked: assert (f_unclocked_q < f_period_ticks);  // the DDA is clocked within a DDA period of ticks in which the FIFO has room, at any timing (hw/README.md)
    if (f_counted_q && fifo_count > f_count_q)
      fifo_fills_on_clocks: assert (f_step_q);  // the FIFO fills only on a tick the DDA is clocked, at any timing (hw/README.md)
  end
`endif
endmodule
