// Formal properties of the DDA's sequencer (tools/girtd formal; hw/formal.json
// lists the instance). A wrapper, not an include: every property here reads
// only the DDA's ports (state_o, out_valid_o), so dda.sv stays as built.
// Labelled asserts are the properties; the comment after each is its row.
// Environment, as the preparer and girtd_backend treat the DDA: reset first;
// the options fixed; every parameter set within the preparer's contract
// (models/dda/README.md, "Limits" and "Start point": the box cut to the
// window, Xmin <= X0 <= Xmax, Y0 <= Ymax). The edge distances, Q and colours
// are free, and hw/formal.json cuts the edge tests (inside, and the sign of
// d/dx that picks a walk's way) so that they may be anything on every clock:
// the walk's end must not depend on them. Enable and back-pressure are free
// too; the bound counts the DDA clocks that act (enabled, not stalled),
// since a receiver that never takes a pixel stops any DDA.
module dda_formal #(
    parameter bit WRAP_DETECT = 1'b1
) (
    input logic clk_i,
    input logic rst_ni,
    input logic en_i,
    input logic walk_fix_i,
    input logic pipelined_compare_i,
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
    input logic out_ready_i
);
  localparam int XY_W = girtd_pkg::XY_W;
  localparam int SB = girtd_pkg::SCREEN_BITS;
  localparam int W = 1 << SB;  // the screen's side
  // Acting DDA clocks from the last offer to idle, for any triangle on the
  // screen: F_ROW per row (a start check; then a walk and a run one way, or a
  // run right and a run left from the same start: at most W pixels either
  // way; a restore, a wait after each compare that needs one, the Y step),
  // W rows, the last check, and the output registers. Argued by hand; the
  // proof confirms it.
  localparam int F_ROW = W + 4;
  localparam int F_IDLE_BOUND = W * F_ROW + 1 + girtd_pkg::OUT_LATENCY;

  logic out_valid, in_ready, active, stall, still;
  logic [girtd_pkg::DDA_STATE_W-1:0] state;
  logic [girtd_pkg::FIFO_X_W-1:0] x_unused;
  logic [girtd_pkg::FIFO_Y_W-1:0] y_unused;
  logic [girtd_pkg::FIFO_R_W-1:0] r_unused;
  logic [girtd_pkg::FIFO_G_W-1:0] g_unused;
  logic [girtd_pkg::FIFO_B_W-1:0] b_unused;
  logic [girtd_pkg::FIFO_NF_W-1:0] nf_unused;
  logic [girtd_pkg::FIFO_Z_W-1:0] z_unused;
  logic [8*girtd_pkg::COUNT_W-1:0] wraps_unused;
  logic [5*girtd_pkg::COUNT_W-1:0] clips_unused;
  logic [girtd_pkg::COUNT_W-1:0] affected_unused, first_unused;
  dda #(.WRAP_DETECT(WRAP_DETECT)) u_dda (
      .clk_i, .rst_ni, .en_i, .walk_fix_i, .pipelined_compare_i, .in_valid_i, .in_ready_o(in_ready),
      .x0_i, .y0_i, .xmin_i, .xmax_i, .ymax_i, .q_zero_i, .q_k_i, .hard_edges_i, .clamped_i,
      .r_i, .r_dx_i, .r_dy_i, .g_i, .g_dx_i, .g_dy_i, .b_i, .b_dx_i, .b_dy_i, .t_i, .t_dx_i, .t_dy_i,
      .z_i, .z_dx_i, .z_dy_i, .d1_i, .d1_dx_i, .d1_dy_i, .d2_i, .d2_dx_i, .d2_dy_i, .d3_i, .d3_dx_i, .d3_dy_i,
      .out_valid_o(out_valid), .out_ready_i,
      .out_x_o(x_unused), .out_y_o(y_unused), .out_r_o(r_unused), .out_g_o(g_unused), .out_b_o(b_unused),
      .out_nf_o(nf_unused), .out_z_o(z_unused), .active_o(active), .stall_o(stall), .state_o(state), .still_o(still),
      .wraps_o(wraps_unused), .clips_o(clips_unused), .triangles_affected_o(affected_unused),
      .first_affected_o(first_unused));

  logic f_past_q = 1'b0;
  logic [1:0] f_options_q;
  always_ff @(posedge clk_i) begin
    f_past_q <= 1'b1;
    f_options_q <= {walk_fix_i, pipelined_compare_i};
  end
  function automatic logic f_on_screen(input logic [XY_W-1:0] v);
    f_on_screen = 32'(v) < W;
  endfunction
  always_comb begin
    if (!f_past_q) assume (!rst_ni);
    if (f_past_q) assume ({walk_fix_i, pipelined_compare_i} == f_options_q);
    if (in_valid_i) assume (f_on_screen(xmin_i) && f_on_screen(xmax_i) && f_on_screen(ymax_i) &&
                            xmin_i <= x0_i && x0_i <= xmax_i && y0_i <= ymax_i);
  end

  // Acting clocks since the last offer, saturating one past the bound (wide
  // enough at any screen size, so that the bound is always reached).
  localparam int F_QUIET_W = $clog2(F_IDLE_BOUND + 2);
  logic [F_QUIET_W-1:0] f_quiet_q;
  always_ff @(posedge clk_i)
    f_quiet_q <= !rst_ni || in_valid_i ? '0
                 : f_quiet_q + F_QUIET_W'(en_i && !(out_valid && !out_ready_i) && f_quiet_q != '1);

  always_comb if (f_past_q && rst_ni) begin
    dda_legal_state: assert (state <= girtd_pkg::S_IDLE);  // the sequencer is only ever in one of its nine states
    if (32'(f_quiet_q) >= F_IDLE_BOUND)
      dda_idle: assert (state == girtd_pkg::S_IDLE && !out_valid);  // input stopped: idle, its pixels handed on, within the bound of acting clocks (hw/README.md)
  end

  logic unused;
  assign unused = ^{in_ready, active, stall, still, x_unused, y_unused, r_unused, g_unused, b_unused, nf_unused, z_unused, wraps_unused, clips_unused, affected_unused,
                    first_unused};
endmodule
