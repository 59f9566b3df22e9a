using System.Collections.Immutable;
using OperatorPanel.Core.Protocol.V3;
using OperatorPanel.StlGen.Model;
using OperatorPanel.StlGen.Options;
using static OperatorPanel.StlGen.Handler.HandlerSnippets;

namespace OperatorPanel.StlGen.V3;

/// <summary>
/// Puts the v3 handler together: OB1's call, OP_PANEL (port set-up, then the request a bounded part per scan: STEP
/// says where it goes on), and the receive, and transmit-complete routines (docs/protocol.md section 6).
/// </summary>
internal static class Builder
{
    public static StlProgram Build(HandlerOptions options, Identity fixedPart)
    {
        ArgumentNullException.ThrowIfNull(options);
        var c = new Context(options);
        var l = c.Layout;
        var panel = ImmutableArray.CreateBuilder<StlNetwork>();
        panel.AddRange(PortPart.Networks(c));
        panel.AddRange(Resumes(c));
        panel.AddRange(CheckPart.Networks(c));
        panel.AddRange(DispatchPart.Networks(c));
        panel.AddRange(DispatchPart.Identify(c, fixedPart));
        panel.AddRange(ItemPart.Commands(c));
        if (c.HasList)
        {
            panel.AddRange(DefinePart.Networks(c));
            panel.AddRange(ListPart.Networks(c));
        }

        if (c.HasStop)
        {
            panel.AddRange(DispatchPart.Stop(c));
        }

        panel.AddRange(ItemPart.Check(c));
        panel.AddRange(ItemPart.Move(c));
        panel.AddRange(CheckPart.ReplyHead(c));
        panel.Add(Label(Labels.Silence, "silence"));
        panel.Add(JumpIf("Silence", "No reply: receive the next request.", Labels.End, Op("LD", "SM0.0"), l.Done(), Op("RCV", l.B(0), c.PortOperand)));
        panel.Add(Label(Labels.Publish, "send what is ready"));
        panel.Add(CheckPart.Publish(c));
        panel.Add(Label(Labels.End, "back to OB1"));
        var first = options.EffectiveFirstInterrupt;
        return new StlProgram(
        [
            new StlBlock(StlBlockKind.Organization, "MAIN", 1, "Main program", [$"Operator panel station {options.Station}: keep network 1 in your OB1."], [PortPart.MainCall(c)]),
            new StlBlock(
                StlBlockKind.Subroutine, c.Names.Panel, options.EffectiveFirstSubroutine, "Operator panel: port set-up and requests",
                [$"Protocol v3 ({(c.HasList ? "full" : "compact")} handler). Freeport on port {c.Port} at RUN, PPI at TERM; serves a received request",
                    "a bounded part per scan (docs/protocol.md section 6). Call from OB1 every scan."], panel.ToImmutable()),
            new StlBlock(
                StlBlockKind.Interrupt, c.Names.Receive, first, "Operator panel: request received",
                [$"Event {c.ReceiveEvent}: a message of LEN bytes for this station waits for {c.Names.Panel}; anything else: receive again."],
                [.. InterruptPart.Receive(c)]),
            new StlBlock(
                StlBlockKind.Interrupt, c.Names.Transmit, first + 1, "Operator panel: reply chunk sent",
                [$"Event {c.TransmitEvent}: the next chunk of the reply, or after its last one receive the next request."], [.. InterruptPart.Transmit(c)]),
        ]);
    }

    /// <summary>
    /// Where OP_PANEL goes on: STEP 0 (no request: the port is receiving or sending) ends the scan's part; otherwise one
    /// contact per phase bit, in <see cref="Phase"/>'s order; the last phase needs no test.
    /// </summary>
    private static IEnumerable<StlNetwork> Resumes(Context c)
    {
        var l = c.Layout;
        yield return JumpIf("No request waiting", "STEP 0: the port is receiving or sending; nothing to do in this scan.", Labels.End, Op("LDW=", l.W(l.Step), "0"));
        var resumes = new List<(Phase Phase, int Label)> { (Phase.Check, Labels.CheckLoop) };
        if (c.HasList)
        {
            resumes.Add((Phase.Gather, Labels.Gather));
        }

        resumes.Add((Phase.Start, Labels.RequestStart));
        if (c.HasList)
        {
            resumes.Add((Phase.Changes, Labels.ChangesLoop));
        }

        resumes.AddRange([(Phase.Reply, Labels.ReplyInR), (Phase.Move, Labels.Move)]);
        if (c.HasList)
        {
            resumes.Add((Phase.Compare, Labels.Compare));
        }

        resumes.Add((Phase.Dispatch, Labels.Dispatch));
        if (c.HasList)
        {
            resumes.AddRange([(Phase.DefineSlot, Labels.DefineItem), (Phase.DefineStore, Labels.DefineStore)]);
        }

        foreach (var (phase, label) in resumes.SkipLast(1))
        {
            yield return JumpIf($"Phase {phase}", $"Go on at label {label}.", label, Op("LD", l.PhaseBit(phase)));
        }

        yield return JumpIf($"Phase {resumes[^1].Phase}", "The only phase left.", resumes[^1].Label, Op("LD", "SM0.0"));
    }
}
