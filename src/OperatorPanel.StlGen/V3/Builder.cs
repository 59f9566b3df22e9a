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
        panel.AddRange(ItemPart.Check(c));
        if (c.HasList)
        {
            panel.AddRange(DefinePart.Networks(c));
            panel.AddRange(ListPart.Networks(c));
        }

        panel.Add(Label(Labels.Silence, "silence"));
        panel.Add(ReturnIf("Silence", "No reply: receive the next request.", Op("LD", "SM0.0"), l.Done(), Op("RCV", l.B(0), c.PortOperand)));

        // From here on each part falls on into the next without a jump: STOP into the reply without payload (label 2),
        // the reply's head into the send of what is ready (label 98), the last network of OP_PANEL.
        if (c.HasStop)
        {
            panel.AddRange(DispatchPart.Stop(c));
        }

        panel.AddRange(CheckPart.ReplyHead(c));
        if (c.SendsInChunks)
        {
            panel.Add(Label(Labels.Publish, "send what is ready"));
            panel.Add(CheckPart.Publish(c));
        }

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
                StlBlockKind.Interrupt, c.Names.Transmit, first + 1, c.SendsInChunks ? "Operator panel: reply chunk sent" : "Operator panel: reply sent",
                [c.SendsInChunks ? $"Event {c.TransmitEvent}: the next chunk of the reply, or after its last one receive the next request." : $"Event {c.TransmitEvent}: the reply is out; receive the next request."], [.. InterruptPart.Transmit(c)]),
        ]);
    }

    /// <summary>
    /// Where OP_PANEL goes on: STEP 0 (no request: the port is receiving or sending) ends the scan's part; then one
    /// test per phase or group of phases (a group found by its bits ORed: contacts take 0.37 us, a jump's test 46 us),
    /// the phases of every request and of an idle READ LIST first, in an order that keeps each scan within its 2 ms:
    /// Check, the list's loops (Compare, then Changes), Start, the heavy steps (Dispatch, DEFINE LIST's two), Reply, Gather,
    /// Move: an idle READ LIST's two Compare scans pass 3 tests (not 5), its Start scan one more, the fullest phases
    /// (Changes, Dispatch: 1.97 ms) as many as before. A phase that is the last left in a group needs no test (SM0.0);
    /// Move, the last of all, needs none and no jump: its networks follow the tests.
    /// </summary>
    private static IEnumerable<StlNetwork> Resumes(Context c)
    {
        var l = c.Layout;
        var used = Enum.GetValues<Phase>().Where(p => p != Phase.ReplyFlag && (c.HasList || !ListPhases.Contains(p))).ToList();
        yield return ReturnIf(
            "No request waiting", "No phase bit in STEP: the port is receiving or sending; nothing to do in this scan (contacts: 0.37 us each, a word compare 46).",
            [.. used.Select((p, i) => Op(i == 0 ? "LDN" : "AN", l.PhaseBit(p)))]);
        (Phase Phase, int Label)[] loops = c.HasList ? [(Phase.Compare, Labels.Compare), (Phase.Changes, Labels.ChangesLoop)] : [];
        (Phase Phase, int Label)[] heavy = c.HasList
            ? [(Phase.Dispatch, Labels.Dispatch), (Phase.DefineSlot, Labels.DefineItem), (Phase.DefineStore, Labels.DefineStore)]
            : [(Phase.Dispatch, Labels.Dispatch)];
        var order = new List<((Phase Phase, int Label)[] Members, int Label)>
        {
            ([(Phase.Check, Labels.CheckLoop)], 0), (loops, Labels.LoopPhases), ([(Phase.Start, Labels.RequestStart)], 0), (heavy, Labels.HeavyPhases),
            ([(Phase.Reply, Labels.ReplyInR)], 0),
        };
        if (c.HasList)
        {
            order.Add(([(Phase.Gather, Labels.Gather)], 0));
        }

        order = [.. order.Where(g => g.Members.Length > 0)];
        for (var i = 0; i < order.Count; i++)
        {
            var (members, label) = order[i];
            if (members.Length == 1)
            {
                yield return PhaseJump(l, members[0], last: false);
                continue;
            }

            yield return JumpIf($"Phases {string.Join(", ", members.Select(m => m.Phase))}", $"Any of their bits: label {label}.", label,
                [.. members.Select((m, k) => Op(k == 0 ? "LD" : "O", l.PhaseBit(m.Phase)))]);
        }

        // The last phase left, Move, follows the tests: no test and no jump (46 us and 3 instructions less). It ends
        // every way with a return, so nothing falls on from it.
        foreach (var network in ItemPart.Move(c))
        {
            yield return network;
        }

        foreach (var (members, label) in order.Where(g => g.Members.Length > 1))
        {
            yield return Label(label, $"phases {string.Join(", ", members.Select(m => m.Phase))}");
            foreach (var network in Chain(l, members))
            {
                yield return network;
            }
        }
    }

    private static readonly Phase[] ListPhases = [Phase.Gather, Phase.Changes, Phase.Compare, Phase.DefineSlot, Phase.DefineStore];

    /// <summary>One test per phase in order; the last one left jumps without a test.</summary>
    private static IEnumerable<StlNetwork> Chain(Layout l, (Phase Phase, int Label)[] phases) =>
        phases.Select((p, i) => PhaseJump(l, p, last: i == phases.Length - 1));

    private static StlNetwork PhaseJump(Layout l, (Phase Phase, int Label) p, bool last) => last
        ? JumpIf($"Phase {p.Phase}", "The only phase left.", p.Label, Op("LD", "SM0.0"))
        : JumpIf($"Phase {p.Phase}", $"Go on at label {p.Label}.", p.Label, Op("LD", l.PhaseBit(p.Phase)));
}
