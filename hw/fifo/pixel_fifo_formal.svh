// Formal properties of pixel_fifo, included into it under `ifdef FORMAL_PIXEL_FIFO
// (tools/girtd formal; hw/formal.json lists the depths proven). Labelled
// asserts are the properties; the comment after each is its table row.
// The environment is the contract girtd_backend keeps (and the simulation
// checks above flag): reset first, a limit fixed between 1 and DEPTH, no
// push into a full FIFO without a pop in the same tick, no pop when empty.
logic f_past_q = 1'b0;  // a tick has gone by (the first one is in reset)
always_ff @(posedge clk_i) f_past_q <= 1'b1;
logic [CW-1:0] f_limit_q;
always_ff @(posedge clk_i) f_limit_q <= limit_i;
always_comb begin
  if (!f_past_q) assume (!rst_ni);
  assume (limit_i >= CW'(1) && 32'(limit_i) <= DEPTH);
  if (f_past_q) assume (limit_i == f_limit_q);
  if (rst_ni) assume ((!push_i || !full_o || pop_i) && (!pop_i || !empty_o));
end

// Pushes minus pops, counted apart from the FIFO.
logic [31:0] f_held_q;
always_ff @(posedge clk_i) f_held_q <= !rst_ni ? '0 : f_held_q + 32'(push_i) - 32'(pop_i);

// One entry, chosen by the solver at any push, followed to the pop that
// takes it: it leaves after exactly the entries that were in before it,
// with its own data. As any entry may be the one, none is lost, duplicated
// or reordered.
(* anyseq *) logic f_choose;
logic f_chosen_q;
logic [W-1:0] f_data_q;
logic [CW-1:0] f_ahead_q;  // entries to leave before it
always_ff @(posedge clk_i) begin
  if (!rst_ni) f_chosen_q <= 1'b0;
  else if (f_chosen_q) begin
    if (pop_i && f_ahead_q == '0) f_chosen_q <= 1'b0;
    else if (pop_i) f_ahead_q <= f_ahead_q - 1'b1;
  end else if (push_i && f_choose) begin
    f_chosen_q <= 1'b1;
    f_data_q <= data_i;
    f_ahead_q <= count_q - CW'(pop_i);
  end
end

always_comb if (f_past_q && rst_ni) begin
  fifo_count: assert (32'(count_o) == f_held_q);  // count == pushes - pops
  fifo_full: assert (full_o == (32'(f_held_q) >= 32'(limit_i)));  // full exactly at the limit
  fifo_empty: assert (empty_o == (f_held_q == 0));  // empty exactly at none held
  fifo_bound: assert (count_q <= limit_i);  // never more than the limit held
  fifo_pointers: assert (32'(wr_q) == (32'(rd_q) + 32'(count_q)) % DEPTH && 32'(rd_q) < DEPTH);  // write = read + count (mod DEPTH)
  if (f_chosen_q) begin
    fifo_order: assert (!pop_i || f_ahead_q != '0 || data_o == f_data_q);  // an entry leaves in its turn with its data: no loss, duplication or reordering
    fifo_stored: assert (f_ahead_q < count_q && mem_q[(32'(rd_q) + 32'(f_ahead_q)) % DEPTH] == f_data_q);  // a held entry sits where its turn will read it
  end
end
