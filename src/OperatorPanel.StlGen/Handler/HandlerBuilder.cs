using System.Collections.Immutable;
using OperatorPanel.StlGen.Model;
using OperatorPanel.StlGen.Options;

namespace OperatorPanel.StlGen.Handler;

/// <summary>
/// Puts the handler's parts together into OB1, one subroutine and three interrupt routines. The receive routine only
/// takes the frame; the subroutine, called every scan, serves it a bounded slice per scan (<see cref="SlicePart"/>).
/// </summary>
internal static class HandlerBuilder
{
    /// <summary>Builds the program; <paramref name="options"/> must have passed <see cref="Diagnostics.HandlerOptionsCheck"/>.</summary>
    public static StlProgram Build(HandlerOptions options)
    {
        ArgumentNullException.ThrowIfNull(options);
        var c = new HandlerContext(options);
        var sbr = options.EffectiveFirstSubroutine;
        var first = options.EffectiveFirstInterrupt;
        var panel = ImmutableArray.CreateBuilder<StlNetwork>();
        panel.AddRange(InitPart.Subroutine(c));
        panel.AddRange(StopPart.Execute(c));
        panel.AddRange(SlicePart.Entry(c));
        panel.AddRange(ReceivePart.Networks(c));
        panel.AddRange(IdentifyPart.Networks(c));
        panel.AddRange(ReadPart.Entry(c));
        panel.AddRange(WritePart.Entries(c));
        panel.AddRange(ListPart.Define(c));
        panel.AddRange(ListPart.Read(c));
        panel.AddRange(ChangesPart.Networks(c));
        panel.AddRange(ChangesOfListsPart.Networks(c));
        panel.AddRange(StopPart.Networks(c));
        panel.AddRange(ItemCheckPart.Networks(c));
        panel.AddRange(ReadPart.Reply(c));
        panel.AddRange(ReadPart.BuildLoop(c));
        panel.AddRange(WritePart.Execute(c));
        panel.AddRange(ReplyPart.Networks(c));
        panel.AddRange(SlicePart.Exit(c));

        return new StlProgram(
        [
            new StlBlock(StlBlockKind.Organization, "MAIN", 1, "Main program", [$"Operator panel station {options.Station}: keep network 1 in your OB1."], [InitPart.MainCall(c)]),
            new StlBlock(
                StlBlockKind.Subroutine, c.Names.Panel, sbr, "Operator panel: port set-up and requests",
                [$"Freeport on port {c.Port} at RUN, PPI at TERM; checks a received request and builds the reply, a bounded part",
                    "per scan (docs/protocol-v2.md section 4). Call from OB1 every scan."], panel.ToImmutable()),
            new StlBlock(
                StlBlockKind.Interrupt, c.Names.Receive, first, "Operator panel: request received",
                [$"Event {c.ReceiveEvent}: a frame ended by '>' for this station waits for {c.Names.Panel}; anything else: receive again."], [.. ReceivePart.Interrupt(c)]),
            new StlBlock(
                StlBlockKind.Interrupt, c.Names.Delay, first + 1, "Operator panel: reply delay",
                [$"Event {HandlerContext.DelayEvent}, timed interrupt 0 (SMB34): sends the reply's first chunk."], [InterruptParts.Delay(c)]),
            new StlBlock(
                StlBlockKind.Interrupt, c.Names.Transmit, first + 2, "Operator panel: reply sent",
                [$"Event {c.TransmitEvent}: the reply's next chunk, or after its last one receive the next request."], [.. InterruptParts.Transmit(c)]),
        ]);
    }
}
