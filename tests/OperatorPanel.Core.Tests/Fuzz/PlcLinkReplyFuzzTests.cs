using System.Diagnostics;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Tests.Protocol;
using OperatorPanel.Core.Transport;
using OperatorPanel.TestKit;

namespace OperatorPanel.Core.Tests.Fuzz;

/// <summary>
/// <see cref="PlcLink"/> over a bus that answers with true, mutated, echoed and late replies (<see cref="MutatingReplyTransport"/>),
/// on the manual clock: an exchange returns only a reply that answers its request, or fails with a
/// <see cref="PlcCommunicationException"/> naming the station and the command (or the vanished port); every attempt is
/// counted; nothing else escapes and nothing hangs; after the port comes back the link answers again.
/// </summary>
public sealed class PlcLinkReplyFuzzTests
{
    [Fact]
    public async Task Exchange_MutatedReplies_AnswersOnlyWithAMatchingReplyElseANamedFailure()
    {
        var random = new Random(9600);
        var clock = new ManualTimeProvider();
        var transport = new MutatingReplyTransport(random, clock);
        var link = new PlcLink(transport, LinkOptions.For(Some.SerialSettings()) with { InterFrameGap = TimeSpan.Zero }, clock);
        var failures = new List<string>();
        var outcomes = new Dictionary<string, int>();
        for (var i = 0; i < 1500; i++)
        {
            var request = RandomMessages.Request(random);
            transport.Current = request;
            transport.Replies.Clear();
            transport.Writes = 0;
            var before = link.StatisticsFor(request.Station);
            var because = $"case {i}, {request.Command}";
            LinkReply reply;
            try
            {
                reply = await RunAsync(link.ExchangeAsync(request, default), clock);
            }
            catch (Exception ex) when (ex is not OutOfMemoryException)
            {
                // The link never throws a link failure: a thrown exception is a bug.
                failures.Add($"{because}: {ex.GetType().Name} {ex.Message}");
                continue;
            }

            string outcome;
            if (reply is LinkReply.Answered { Response: var response })
            {
                var chars = ResponseCodec.Encode(response);
                outcome = response is ErrorResponse ? "refusal" : "answer";
                if (!transport.Replies.Any(r => r.MayBeAccepted && r.Chars.AsSpan().EndsWith(chars)) && !RepeatedCorruptedRefusal(response, transport.Replies))
                {
                    failures.Add($"{because}: answered with a reply the bus never sent as a valid one ({string.Join("; ", transport.Replies.Select(r => r.How))})");
                }
            }
            else
            {
                var ex = reply.Failure!;
                outcome = ex.Kind.ToString();
                if (ex.Kind == PlcErrorKind.PortUnavailable)
                {
                    if (ex.Station != request.Station || !ex.Message.Contains(transport.Name, StringComparison.Ordinal) || !ex.Message.Contains("vanished", StringComparison.Ordinal))
                    {
                        failures.Add($"{because}: a vanished port not named as such: {ex.Message}");
                    }
                }
                else if (ex.Kind is not (PlcErrorKind.NoAnswer or PlcErrorKind.FrameCorrupt) || ex.Station != request.Station
                    || !ex.Message.Contains(request.Station.ToString(), StringComparison.Ordinal) || !ex.Message.Contains(request.Command.ToString(), StringComparison.Ordinal))
                {
                    failures.Add($"{because}: failure does not name the station and command: {ex.Kind} {ex.Message}");
                }
                else if (transport.Replies.FirstOrDefault() is { How: "untouched" } && request is not (WriteBlockRequest or WriteBitRequest or StopRequest))
                {
                    failures.Add($"{because}: the first reply was true, yet the exchange failed: {ex.Message}");
                }
            }

            outcomes[outcome] = outcomes.GetValueOrDefault(outcome) + 1;
            var after = link.StatisticsFor(request.Station);
            if (request is not IdentifyRequest && outcome != nameof(PlcErrorKind.PortUnavailable) && after.Requests - before.Requests != transport.Writes)
            {
                failures.Add($"{because}: {transport.Writes} frames sent, {after.Requests - before.Requests} requests counted");
            }
        }

        failures.Should().BeEmpty();
        outcomes.Keys.Should().Contain(["answer", "refusal", nameof(PlcErrorKind.NoAnswer), nameof(PlcErrorKind.FrameCorrupt), nameof(PlcErrorKind.PortUnavailable)], "the cases reach every outcome");
    }

    /// <summary>
    /// Runs the exchange, moving the manual clock only while the link waits on a timer (its reopen interval after a
    /// vanished port): the transport moves the clock itself for a read that gets nothing, and a clock moved while the
    /// link was between its write and its read could time out a reply that is waiting. The wall-clock limit only
    /// catches a hang.
    /// </summary>
    private static async Task<LinkReply> RunAsync(Task<LinkReply> exchange, ManualTimeProvider clock)
    {
        var wallClock = Stopwatch.StartNew();
        while (!exchange.IsCompleted && wallClock.Elapsed < TimeSpan.FromSeconds(10))
        {
            if (clock.ActiveTimers > 0)
            {
                clock.Advance(TimeSpan.FromMilliseconds(50));
            }

            await Task.Yield();
        }

        return await exchange.WaitAsync(TimeSpan.FromSeconds(1));
    }

    /// <summary>
    /// docs/protocol-v2.md, REQCHECK: a refusal of a corrupted copy is retried once, and a refusal that comes again is taken
    /// as real, whatever REQCHECK it carries.
    /// </summary>
    private static bool RepeatedCorruptedRefusal(PlcResponse response, List<ReplyMutation> replies) =>
        response is ErrorResponse && replies.Count(r => r.How.StartsWith("REQCHECK", StringComparison.Ordinal)
            && FrameCodec.TryDecode(r.Chars, out var frame, out _) && frame.Payload[0] != 0) >= 2;
}
