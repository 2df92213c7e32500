// Measurement shell, not part of GIRTD: the whole DDA behind a serial input
// register chain and an XOR-folded output register, so an iCE40 flow can
// place it with a handful of pins and time its internal paths.
module cost_shell_dda (
    input  logic clk_i,
    input  logic rst_ni,
    input  logic serial_i,
    output logic serial_o
);
  localparam int XY = girtd_pkg::XY_W, C = girtd_pkg::COLOR_W, T = girtd_pkg::T_W, Z = girtd_pkg::Z_W,
                 D = girtd_pkg::D_W;
  localparam int K = girtd_pkg::Q_K_W, B = 4 + 5 * XY + K;  // B: where R starts, after q_k
  localparam int N = 5 * XY + 1 + K + 9 * C + 3 * T + 3 * Z + 9 * D + 4 + 3;  // + 3: edge flags, before out_ready
  logic [N-1:0] sr_q;
  always_ff @(posedge clk_i) sr_q <= {sr_q[N-2:0], serial_i};

  logic out_valid, in_ready, active, stall;
  logic [girtd_pkg::FIFO_X_W-1:0] ox;
  logic [girtd_pkg::FIFO_Y_W-1:0] oy;
  logic [girtd_pkg::FIFO_R_W-1:0] orr;
  logic [girtd_pkg::FIFO_G_W-1:0] og;
  logic [girtd_pkg::FIFO_B_W-1:0] ob;
  logic [girtd_pkg::FIFO_NF_W-1:0] onf;
  logic [girtd_pkg::FIFO_Z_W-1:0] oz;
  logic [girtd_pkg::DDA_STATE_W-1:0] state;
  dda #(.WRAP_DETECT(1'b0)) u_dda (
      .clk_i, .rst_ni, .en_i(1'b1), .walk_fix_i(sr_q[0]), .pipelined_compare_i(sr_q[1]), .in_valid_i(sr_q[2]),
      .in_ready_o(in_ready), .x0_i(sr_q[3+:XY]), .y0_i(sr_q[3+XY+:XY]), .xmin_i(sr_q[3+2*XY+:XY]),
      .xmax_i(sr_q[3+3*XY+:XY]), .ymax_i(sr_q[3+4*XY+:XY]), .q_zero_i(sr_q[3+5*XY]), .q_k_i(sr_q[4+5*XY+:K]),
      .hard_edges_i(sr_q[N-4+:3]), .clamped_i(1'b0),
      .r_i(sr_q[B+:C]), .r_dx_i(sr_q[B+C+:C]), .r_dy_i(sr_q[B+2*C+:C]),
      .g_i(sr_q[B+3*C+:C]), .g_dx_i(sr_q[B+4*C+:C]), .g_dy_i(sr_q[B+5*C+:C]),
      .b_i(sr_q[B+6*C+:C]), .b_dx_i(sr_q[B+7*C+:C]), .b_dy_i(sr_q[B+8*C+:C]),
      .t_i(sr_q[B+9*C+:T]), .t_dx_i(sr_q[B+9*C+T+:T]), .t_dy_i(sr_q[B+9*C+2*T+:T]),
      .z_i(sr_q[B+9*C+3*T+:Z]), .z_dx_i(sr_q[B+9*C+3*T+Z+:Z]), .z_dy_i(sr_q[B+9*C+3*T+2*Z+:Z]),
      .d1_i(sr_q[B+9*C+3*T+3*Z+:D]), .d1_dx_i(sr_q[B+9*C+3*T+3*Z+D+:D]),
      .d1_dy_i(sr_q[B+9*C+3*T+3*Z+2*D+:D]), .d2_i(sr_q[B+9*C+3*T+3*Z+3*D+:D]),
      .d2_dx_i(sr_q[B+9*C+3*T+3*Z+4*D+:D]), .d2_dy_i(sr_q[B+9*C+3*T+3*Z+5*D+:D]),
      .d3_i(sr_q[B+9*C+3*T+3*Z+6*D+:D]), .d3_dx_i(sr_q[B+9*C+3*T+3*Z+7*D+:D]),
      .d3_dy_i(sr_q[B+9*C+3*T+3*Z+8*D+:D]),
      .out_valid_o(out_valid), .out_ready_i(sr_q[N-1]), .out_x_o(ox), .out_y_o(oy), .out_r_o(orr),
      .out_g_o(og), .out_b_o(ob), .out_nf_o(onf), .out_z_o(oz), .active_o(active), .stall_o(stall),
      .state_o(state), .still_o(), .wraps_o(), .clips_o(), .triangles_affected_o(), .first_affected_o());
  always_ff @(posedge clk_i) serial_o <= ^{out_valid, in_ready, active, stall, ox, oy, orr, og, ob, onf, oz, state};
endmodule
