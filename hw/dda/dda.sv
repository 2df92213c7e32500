// The GIRTD DDA (§4): ten element processors and the sequencer of
// models/dda/README.md. One clock = one operation on every EP (a unit move,
// an AUX save or restore, or nothing). Bit-exact with models/dda/dda_engine.
//
// Parameter sets arrive on a valid/ready port (from the preparer's FIFO);
// pixels leave on a valid/ready port (to the DDA->HAD FIFO) after
// OUT_LATENCY output-register stages (fig. 4.17). While the last stage holds
// a pixel the receiver does not take, the whole DDA waits (stall_o).
module dda #(
    parameter bit WRAP_DETECT = 1'b1  // the EPs' guard bits and the numerics counters (0: the thesis' datapath alone)
) (
    input  logic clk_i,
    input  logic rst_ni,
    input  logic en_i,  // clock enable: the DDA acts on enabled base ticks only (one DDA clock each)
    // Run-time options (config/girtd.json: dda.walk_fix, dda.xy_compare_pipelined)
    input  logic walk_fix_i,
    input  logic pipelined_compare_i,
    // Parameter set of one triangle
    input  logic                                         in_valid_i,
    output logic                                         in_ready_o,
    input  logic [girtd_pkg::XY_W-1:0]                   x0_i,
    input  logic [girtd_pkg::XY_W-1:0]                   y0_i,
    input  logic [girtd_pkg::XY_W-1:0]                   xmin_i,
    input  logic [girtd_pkg::XY_W-1:0]                   xmax_i,
    input  logic [girtd_pkg::XY_W-1:0]                   ymax_i,
    input  logic                                         q_zero_i,
    input  logic signed [girtd_pkg::Q_K_W-1:0]          q_k_i,
    input  logic [2:0]                                   hard_edges_i,  // edge flags: D(i+1) has no fringe
    input  logic                                         clamped_i,     // the preparer clamped a value (counted only)
    input  logic signed [girtd_pkg::COLOR_W-1:0]         r_i, r_dx_i, r_dy_i,
    input  logic signed [girtd_pkg::COLOR_W-1:0]         g_i, g_dx_i, g_dy_i,
    input  logic signed [girtd_pkg::COLOR_W-1:0]         b_i, b_dx_i, b_dy_i,
    input  logic signed [girtd_pkg::T_W-1:0]             t_i, t_dx_i, t_dy_i,
    input  logic signed [girtd_pkg::Z_W-1:0]             z_i, z_dx_i, z_dy_i,
    input  logic signed [girtd_pkg::D_W-1:0]             d1_i, d1_dx_i, d1_dy_i,
    input  logic signed [girtd_pkg::D_W-1:0]             d2_i, d2_dx_i, d2_dy_i,
    input  logic signed [girtd_pkg::D_W-1:0]             d3_i, d3_dx_i, d3_dy_i,
    // Pixel out: the fields of the FIFO word (girtd_pkg::FIFO_*)
    output logic                                 out_valid_o,
    input  logic                                 out_ready_i,
    output logic [girtd_pkg::FIFO_X_W-1:0]       out_x_o,
    output logic [girtd_pkg::FIFO_Y_W-1:0]       out_y_o,
    output logic [girtd_pkg::FIFO_R_W-1:0]       out_r_o,
    output logic [girtd_pkg::FIFO_G_W-1:0]       out_g_o,
    output logic [girtd_pkg::FIFO_B_W-1:0]       out_b_o,
    output logic [girtd_pkg::FIFO_NF_W-1:0]      out_nf_o,
    output logic [girtd_pkg::FIFO_Z_W-1:0]       out_z_o,
    // Observation: a counted DDA clock, a clock lost to back-pressure, the state
    output logic                                 active_o,
    output logic                                 stall_o,
    output logic [girtd_pkg::DDA_STATE_W-1:0]    state_o,
    // An enabled clock now would change nothing but the wait count: stalled,
    // or idle with its output registers empty (a parameter set offered on
    // in_valid_i is the driver's to know). For hw/backend's tick warp.
    output logic                                 still_o,
    // Numerics (report.json `numerics`, models/dda/ep_numerics.hpp): per EP in
    // the order R, G, B, T, Z, D1, D2, D3, clocks or pixels that used a
    // wrapped value; per R, G, B, T, Z pixels whose output clipped
    output logic [8*girtd_pkg::COUNT_W-1:0]      wraps_o,
    output logic [5*girtd_pkg::COUNT_W-1:0]      clips_o,
    output logic [girtd_pkg::COUNT_W-1:0]        triangles_affected_o,
    output logic [girtd_pkg::COUNT_W-1:0]        first_affected_o  // numbered from 1 among the parameter sets taken (0: none)
);
  localparam int XY_W = girtd_pkg::XY_W;
  localparam int L = girtd_pkg::OUT_LATENCY;

  // State encoding generated from models/dda (DdaState), so traces compare directly.
  localparam int SW = girtd_pkg::DDA_STATE_W;
  localparam logic [SW-1:0] S_CHECK = girtd_pkg::S_CHECK, S_RIGHT = girtd_pkg::S_RIGHT, S_LSTEP = girtd_pkg::S_LSTEP,
                            S_LEFT = girtd_pkg::S_LEFT, S_WALK = girtd_pkg::S_WALK, S_RUN = girtd_pkg::S_RUN,
                            S_YSTEP = girtd_pkg::S_YSTEP, S_WAIT = girtd_pkg::S_WAIT, S_IDLE = girtd_pkg::S_IDLE;
  localparam int SB = girtd_pkg::SCREEN_BITS;

  logic [SW-1:0] state_q, state_d, after_wait_q, after_wait_d;
  logic walk_left_q, walk_left_d, first_q, first_d;
  logic [XY_W-1:0] xmin_q, xmax_q, ymax_q;
  logic q_zero_q;
  logic [2:0] hard_q;
  logic signed [girtd_pkg::Q_K_W-1:0] q_k_q;
  logic [girtd_pkg::OP_W-1:0] op;  // the sequencer's operation (never OP_LOAD: `load` is apart)
  logic load, emit, stall;

  // ---- Element processors ----
  logic [XY_W-1:0] x, y;
  logic signed [girtd_pkg::COLOR_W-1:0] r, g, b, r_dx_unused, g_dx_unused, b_dx_unused;
  logic signed [girtd_pkg::T_W-1:0] t, t_dx_unused;
  logic signed [girtd_pkg::Z_W-1:0] z, z_dx_unused;
  logic signed [girtd_pkg::D_W-1:0] d[3], d_dx[3];
  logic [7:0] wrapped;  // R, G, B, T, Z, D1, D2, D3
  localparam int GC = WRAP_DETECT ? girtd_pkg::COLOR_GUARD : 0, GT = WRAP_DETECT ? girtd_pkg::T_GUARD : 0,
                 GZ = WRAP_DETECT ? girtd_pkg::Z_GUARD : 0, GD = WRAP_DETECT ? girtd_pkg::D_GUARD : 0;

  dda_counter #(.W(XY_W), .INC_OP(girtd_pkg::OP_XINC), .DEC_OP(girtd_pkg::OP_XDEC))
      u_x (.clk_i, .load_i(load), .op_i(op), .value_i(x0_i), .value_o(x));
  dda_counter #(.W(XY_W), .INC_OP(girtd_pkg::OP_YINC), .CAN_DEC(1'b0))
      u_y (.clk_i, .load_i(load), .op_i(op), .value_i(y0_i), .value_o(y));
  dda_ep #(.W(girtd_pkg::COLOR_W), .G(GC)) u_r (.clk_i, .load_i(load), .op_i(op), .value_i(r_i), .dx_i(r_dx_i), .dy_i(r_dy_i),
                                        .value_o(r), .dx_o(r_dx_unused), .wrapped_o(wrapped[0]));
  dda_ep #(.W(girtd_pkg::COLOR_W), .G(GC)) u_g (.clk_i, .load_i(load), .op_i(op), .value_i(g_i), .dx_i(g_dx_i), .dy_i(g_dy_i),
                                        .value_o(g), .dx_o(g_dx_unused), .wrapped_o(wrapped[1]));
  dda_ep #(.W(girtd_pkg::COLOR_W), .G(GC)) u_b (.clk_i, .load_i(load), .op_i(op), .value_i(b_i), .dx_i(b_dx_i), .dy_i(b_dy_i),
                                        .value_o(b), .dx_o(b_dx_unused), .wrapped_o(wrapped[2]));
  dda_ep #(.W(girtd_pkg::T_W), .G(GT)) u_t (.clk_i, .load_i(load), .op_i(op), .value_i(t_i), .dx_i(t_dx_i), .dy_i(t_dy_i),
                                    .value_o(t), .dx_o(t_dx_unused), .wrapped_o(wrapped[3]));
  dda_ep #(.W(girtd_pkg::Z_W), .G(GZ)) u_z (.clk_i, .load_i(load), .op_i(op), .value_i(z_i), .dx_i(z_dx_i), .dy_i(z_dy_i),
                                    .value_o(z), .dx_o(z_dx_unused), .wrapped_o(wrapped[4]));
  dda_ep #(.W(girtd_pkg::D_W), .G(GD)) u_d1 (.clk_i, .load_i(load), .op_i(op), .value_i(d1_i), .dx_i(d1_dx_i), .dy_i(d1_dy_i),
                                     .value_o(d[0]), .dx_o(d_dx[0]), .wrapped_o(wrapped[5]));
  dda_ep #(.W(girtd_pkg::D_W), .G(GD)) u_d2 (.clk_i, .load_i(load), .op_i(op), .value_i(d2_i), .dx_i(d2_dx_i), .dy_i(d2_dy_i),
                                     .value_o(d[1]), .dx_o(d_dx[1]), .wrapped_o(wrapped[6]));
  dda_ep #(.W(girtd_pkg::D_W), .G(GD)) u_d3 (.clk_i, .load_i(load), .op_i(op), .value_i(d3_i), .dx_i(d3_dx_i), .dy_i(d3_dy_i),
                                     .value_o(d[2]), .dx_o(d_dx[2]), .wrapped_o(wrapped[7]));

  // ---- Coverage, nf and the output stages ----
  logic [2:0] d_inside;
  logic [girtd_pkg::NF_W-1:0] n[3];
  for (genvar i = 0; i < 3; i++) begin : g_norm
    dda_norm #(.W(girtd_pkg::D_W), .FRAC(girtd_pkg::D_FRAC), .NF(girtd_pkg::NORM_FRAC))
        u_norm (.d_i(d[i]), .q_zero_i(q_zero_q || hard_q[i]), .q_k_i(q_k_q), .inside_o(d_inside[i]), .n_o(n[i]));
  end

  logic [girtd_pkg::COLOR_OUT-1:0] r8, g8, b8;
  logic [girtd_pkg::T_OUT-1:0] t8;
  logic [girtd_pkg::Z_OUT-1:0] z16;
  logic [girtd_pkg::NF_W-1:0] nf;
  logic [4:0] clipped;  // R, G, B, T, Z outputs clipped to their range
  dda_saturate #(.W(girtd_pkg::COLOR_W), .FRAC(girtd_pkg::COLOR_FRAC), .OUT(girtd_pkg::COLOR_OUT)) u_sat_r (.value_i(r), .out_o(r8), .clipped_o(clipped[0]));
  dda_saturate #(.W(girtd_pkg::COLOR_W), .FRAC(girtd_pkg::COLOR_FRAC), .OUT(girtd_pkg::COLOR_OUT)) u_sat_g (.value_i(g), .out_o(g8), .clipped_o(clipped[1]));
  dda_saturate #(.W(girtd_pkg::COLOR_W), .FRAC(girtd_pkg::COLOR_FRAC), .OUT(girtd_pkg::COLOR_OUT)) u_sat_b (.value_i(b), .out_o(b8), .clipped_o(clipped[2]));
  dda_saturate #(.W(girtd_pkg::T_W), .FRAC(girtd_pkg::T_FRAC), .OUT(girtd_pkg::T_OUT)) u_sat_t (.value_i(t), .out_o(t8), .clipped_o(clipped[3]));
  dda_saturate #(.W(girtd_pkg::Z_W), .FRAC(girtd_pkg::Z_FRAC), .OUT(girtd_pkg::Z_OUT)) u_sat_z (.value_i(z), .out_o(z16), .clipped_o(clipped[4]));
  // T = 255 at the output means exactly 1.0.
  localparam logic [girtd_pkg::NF_W-1:0] NF_ONE = girtd_pkg::NF_W'(1) << girtd_pkg::NORM_FRAC;
  dda_nf u_nf (.n1_i(n[0]), .n2_i(n[1]), .n3_i(n[2]), .t_i(t8 == '1 ? NF_ONE : girtd_pkg::NF_W'(t8)), .nf_o(nf));

  // ---- Sequencer decisions on the registers as they stand ----
  logic in_limits, pix_inside, y_past_end;
  logic dir_left, dir_none;  // DIR: which way back in; none = no horizontal way (fix)
  assign in_limits = x >= xmin_q && x <= xmax_q;
  assign pix_inside = in_limits && (&d_inside);
  assign y_past_end = y > ymax_q;

  always_comb begin
    dir_left = 1'b0;
    dir_none = 1'b0;
    if (x < xmin_q) dir_left = 1'b0;
    else if (x > xmax_q) dir_left = 1'b1;
    else if (!d_inside[0]) {dir_left, dir_none} = {d_dx[0] < 0, walk_fix_i && d_dx[0] == 0};
    else if (!d_inside[1]) {dir_left, dir_none} = {d_dx[1] < 0, walk_fix_i && d_dx[1] == 0};
    else if (!d_inside[2]) {dir_left, dir_none} = {d_dx[2] < 0, walk_fix_i && d_dx[2] == 0};
  end

  function automatic logic can_step(input logic left, input logic [XY_W-1:0] xv, input logic [XY_W-1:0] lo,
                                    input logic [XY_W-1:0] hi);
    can_step = left ? xv > lo : xv < hi;
  endfunction

  function automatic logic [girtd_pkg::OP_W-1:0] step_op(input logic left);
    step_op = left ? girtd_pkg::OP_XDEC : girtd_pkg::OP_XINC;
  endfunction

  always_comb begin
    op = girtd_pkg::OP_NONE;
    emit = 1'b0;
    state_d = state_q;
    after_wait_d = after_wait_q;
    walk_left_d = walk_left_q;
    first_d = first_q;
    if (!hold) begin
      unique case (state_q)
        S_IDLE: ;  // the load (below) is the one decision on an input
        S_CHECK: begin
          first_d = 1'b0;
          if (y_past_end) state_d = S_IDLE;
          else if (pix_inside) begin
            op = girtd_pkg::OP_SAVE;
            state_d = S_RIGHT;
          end else if (!walk_fix_i && first_q) op = girtd_pkg::OP_YINC;  // DDApix skips the row
          else begin
            walk_left_d = dir_left;
            if (dir_none) op = girtd_pkg::OP_YINC;
            else if (!can_step(dir_left, x, xmin_q, xmax_q)) begin
              if (walk_fix_i) op = girtd_pkg::OP_YINC;
              else state_d = S_IDLE;
            end else begin
              op = step_op(dir_left);
              state_d = S_WALK;
            end
          end
        end
        S_WALK: begin
          if (pix_inside) begin
            op = girtd_pkg::OP_SAVE;
            state_d = S_RUN;
          end else if (walk_fix_i && (dir_none || dir_left != walk_left_q)) begin
            op = girtd_pkg::OP_YINC;  // walked across a row with no pixel
            state_d = S_CHECK;
          end else if (!can_step(walk_left_q, x, xmin_q, xmax_q)) begin
            if (walk_fix_i) begin
              op = girtd_pkg::OP_YINC;
              state_d = S_CHECK;
            end else state_d = S_IDLE;
          end else op = step_op(walk_left_q);
        end
        S_RIGHT: begin
          emit = pix_inside;
          if (pix_inside && x < xmax_q) op = girtd_pkg::OP_XINC;
          else begin
            op = girtd_pkg::OP_RESTORE;
            state_d = pipelined_compare_i ? S_WAIT : S_LSTEP;
            after_wait_d = S_LSTEP;
          end
        end
        S_LSTEP: begin
          if (x > xmin_q) begin
            op = girtd_pkg::OP_XDEC;
            state_d = S_LEFT;
          end else begin
            op = girtd_pkg::OP_YINC;
            state_d = pipelined_compare_i ? S_WAIT : S_CHECK;
            after_wait_d = S_CHECK;
          end
        end
        S_LEFT: begin
          emit = pix_inside;
          if (pix_inside && x > xmin_q) op = girtd_pkg::OP_XDEC;
          else begin
            op = girtd_pkg::OP_YINC;
            state_d = pipelined_compare_i ? S_WAIT : S_CHECK;
            after_wait_d = S_CHECK;
          end
        end
        S_RUN: begin
          emit = pix_inside;
          if (pix_inside && can_step(walk_left_q, x, xmin_q, xmax_q)) op = step_op(walk_left_q);
          else begin
            op = girtd_pkg::OP_RESTORE;
            state_d = pipelined_compare_i ? S_WAIT : S_YSTEP;
            after_wait_d = S_YSTEP;
          end
        end
        S_YSTEP: begin
          op = girtd_pkg::OP_YINC;
          state_d = S_CHECK;
        end
        S_WAIT: state_d = after_wait_q;
        default: state_d = S_IDLE;
      endcase
    end
  end

  // Taking a parameter set: IDLE on an enabled clock with one offered. Kept
  // out of the sequencer's case so that only this gate, the EPs' load muxes
  // and the limit registers depend on the input port.
  assign load = state_q == S_IDLE && !hold && in_valid_i;

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      state_q <= S_IDLE;
      after_wait_q <= S_CHECK;
      walk_left_q <= 1'b0;
      first_q <= 1'b0;
    end else begin
      state_q <= load ? S_CHECK : state_d;
      after_wait_q <= after_wait_d;
      walk_left_q <= walk_left_d;
      first_q <= load || first_d;
    end
    if (load) begin
      xmin_q <= xmin_i;
      xmax_q <= xmax_i;
      ymax_q <= ymax_i;
      q_zero_q <= q_zero_i;
      q_k_q <= q_k_i;
      hard_q <= hard_edges_i;
    end
  end

  // ---- Output registers (fig. 4.17): OUT_LATENCY stages, frozen by a stall ----
  logic [girtd_pkg::FIFO_W-1:0] pipe_q[L];
  logic valid_q[L];
  // A disabled tick freezes everything, like a stall, but is not counted as one.
  logic hold;
  assign stall = valid_q[L-1] && !out_ready_i;
  assign hold = stall || !en_i;

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      for (int i = 0; i < L; i++) valid_q[i] <= 1'b0;
    end else if (!hold) begin
      valid_q[0] <= emit;
      pipe_q[0] <= {x[SB-1:0], y[SB-1:0], r8, g8, b8, nf, z16};
      for (int i = 1; i < L; i++) begin
        valid_q[i] <= valid_q[i-1];
        pipe_q[i] <= pipe_q[i-1];
      end
    end
  end

  assign {out_x_o, out_y_o, out_r_o, out_g_o, out_b_o, out_nf_o, out_z_o} = pipe_q[L-1];
  assign out_valid_o = valid_q[L-1];
  assign in_ready_o = state_q == S_IDLE && !hold;
  assign active_o = state_q != S_IDLE && !hold;
  assign stall_o = en_i && stall && state_q != S_IDLE;
  assign state_o = state_q;
  logic out_regs_empty;
  always_comb begin
    out_regs_empty = 1'b1;
    for (int i = 0; i < L; i++) if (valid_q[i]) out_regs_empty = 1'b0;
  end
  assign still_o = stall || (state_q == S_IDLE && out_regs_empty);

  // ---- Numerics: the clocks that read D1..D3 (as models/dda counts them:
  // every test of the edges within the X limits) and the emitted pixels ----
  logic d_read, tri_end, t_is_one;
  assign d_read = !hold && in_limits && ((state_q == S_CHECK && !y_past_end) || state_q == S_WALK ||
                                         state_q == S_RIGHT || state_q == S_LEFT || state_q == S_RUN);
  assign tri_end = !hold && state_q != S_IDLE && state_d == S_IDLE;
  // T = 1.0 (256) is carried out as 255 by design: not a clip. Needs 10
  // integer bits to be held at all (as models/dda tests it).
  localparam int T_INT = girtd_pkg::T_W - girtd_pkg::T_FRAC;
  if (T_INT >= 10) begin : g_t_one
    assign t_is_one = t[girtd_pkg::T_W-1:girtd_pkg::T_FRAC] == T_INT'(256);
  end else begin : g_t_no_one
    assign t_is_one = 1'b0;
  end
  if (WRAP_DETECT) begin : g_limits
    dda_limits u_limits (
        .clk_i, .rst_ni, .load_i(load), .clamped_i, .end_i(tri_end),
        .wrap_use_i({{3{d_read}} & wrapped[7:5], {5{emit}} & wrapped[4:0]}),
        .clip_i({5{emit}} & {clipped[4], clipped[3] && !t_is_one, clipped[2:0]}),
        .wraps_o, .clips_o, .triangles_affected_o, .first_affected_o);
  end else begin : g_no_limits
    assign wraps_o = '0;
    assign clips_o = '0;
    assign triangles_affected_o = '0;
    assign first_affected_o = '0;
    logic unused_limits;
    assign unused_limits = ^{d_read, tri_end, t_is_one, wrapped, clipped, clamped_i};
  end

`ifdef GIRTD_COVER
  // Functional coverage (check build, verilator --coverage): every sequencer
  // state, both walk directions, and every row of the U decoder on an emitted
  // pixel. testbench/rtl reads coverage.dat and fails on a point never hit.
  for (genvar st = 0; st <= int'(S_IDLE); st++) begin : g_cover_state
    cover property (@(posedge clk_i) state_q == SW'(st));
  end
  cover property (@(posedge clk_i) state_q == S_WALK && !walk_left_q);
  cover property (@(posedge clk_i) state_q == S_WALK && walk_left_q);
  for (genvar row = 0; row < 16; row++) begin : g_cover_nf_row
    cover property (@(posedge clk_i) emit && u_nf.row == 4'(row));
  end
`endif

  // Unused by design: the colour, T and Z EPs' d/dx are only needed by DIR for D.
  logic unused;
  assign unused = ^{r_dx_unused, g_dx_unused, b_dx_unused, t_dx_unused, z_dx_unused, x[XY_W-1:SB], y[XY_W-1:SB]};
endmodule
