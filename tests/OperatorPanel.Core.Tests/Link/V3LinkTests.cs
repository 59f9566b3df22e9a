using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Link.V3;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Protocol.V3;
using OperatorPanel.Core.Transport;
using OperatorPanel.TestKit;

namespace OperatorPanel.Core.Tests.Link;

/// <summary>
/// The v3 link's exchange rules with a fake station (<see cref="Responder"/>): REQCHECK matching, what is skipped, what
/// is retried and what is sent once, and what v3 cannot carry.
/// </summary>
public sealed class V3LinkTests
{
    private static readonly Station Two = new(2);

    [Fact]
    public async Task ExchangeV3_ReadListReplyLost_SentOnceNeverRepeated()
    {
        var (link, station) = Create(_ => null);

        var exchange = await link.ExchangeV3Async(Request.ReadList(Two, 0), default);

        exchange.Failure!.Kind.Should().Be(PlcErrorKind.NoAnswer);
        exchange.Failure.Message.Should().Contain("sent once, never repeated");
        station.Received.Should().HaveCount(1);
    }

    [Fact]
    public async Task ExchangeV3_ReadReplyLost_RetriedTwice()
    {
        var (link, station) = Create(_ => null);

        var exchange = await link.ExchangeV3Async(Request.Read(Two, 0, new ReadItem(ProtocolArea.V, 0, 1)), default);

        exchange.Failure!.Kind.Should().Be(PlcErrorKind.NoAnswer);
        station.Received.Should().HaveCount(5, "3 READs, then once per station the v2 and v1 IDENTIFY asking whether an older handler is there");
        station.Received.Take(3).Distinct(new BytesComparer()).Should().HaveCount(1, "a retry repeats the identical frame");
    }

    [Fact]
    public async Task ExchangeV3_ReplyFailsItsCheckOnce_RetriedAndAnswered()
    {
        var replies = 0;
        var (link, station) = Create(request =>
        {
            var reply = Codec.Encode(new Reply(ReplyStatus.Ok, Codec.RequestCheckOf(request), [0x42]));
            if (replies++ == 0)
            {
                reply[5] ^= 0x01;
            }

            return [reply];
        });

        var exchange = await link.ExchangeV3Async(Request.Read(Two, 0, new ReadItem(ProtocolArea.V, 0, 1)), default);

        exchange.Reply!.Payload.Should().Equal(0x42);
        station.Received.Should().HaveCount(2);
        link.StatisticsFor(Two).Should().BeEquivalentTo(new { Retries = 1, CorruptFrames = 1, Replies = 1 });
    }

    [Fact]
    public async Task Exchange_EchoOfOurRequestThenTheReply_EchoSkipped()
    {
        var (link, _) = Create(request => [request, Codec.Encode(new Reply(ReplyStatus.Ok, Codec.RequestCheckOf(request), [0x07]))]);

        var reply = await link.ExchangeAsync(new ReadRequest(Two, [new ReadItem(ProtocolArea.M, 3, 1)]), default);

        reply.Response.Should().BeOfType<ReadResponse>().Which.Data.Should().Equal(0x07);
    }

    [Fact]
    public async Task Exchange_WriteAnsweredForAnotherFrame_FailsAsACorruptedCopy_SentOnce()
    {
        var (link, station) = Create(request => [Codec.Encode(new Reply(ReplyStatus.Ok, (ushort)(Codec.RequestCheckOf(request) ^ 0x0100), [0x01]))]);

        var reply = await link.ExchangeAsync(new WriteBlockRequest(Two, ProtocolArea.V, 10, [0x01]), default);

        var failed = reply.Should().BeOfType<LinkReply.Failed>().Subject;
        (failed.Sent, failed.CorruptedCopy, failed.Failure.Kind).Should().Be((true, true, PlcErrorKind.FrameCorrupt));
        station.Received.Should().HaveCount(1);
    }

    [Theory]
    [InlineData(10, 0)] // scans shorter than the options' 30 ms allowance change nothing
    [InlineData(100, 125)] // a 100 ms scan is allowed 125 ms: READ's 9 scans and the one before it
    public async Task ReplyTimeout_AfterIdentifyReportsItsLongestScan_AllowsEveryScanThatLong(int maxScanMs, int perScanMs)
    {
        var identity = new Identity(1, 0x20, 0, 0x0E, 1, 4, 0, 137, 16, 32, 128, 7586, 606, 0x20, 1, 5, 2, (ushort)maxScanMs);
        var (link, _) = Create(request => [Codec.Encode(new Reply(ReplyStatus.Ok, Codec.RequestCheckOf(request), identity.ToPayload()))]);
        var before = link.ReplyTimeoutFor(Command.Read, 12);

        (await link.ExchangeAsync(new IdentifyRequest(Two), default)).Response.Should().BeOfType<IdentifyResponse>();

        var after = link.ReplyTimeoutFor(Command.Read, 12);
        var expected = perScanMs == 0 ? TimeSpan.Zero
            : (TimeSpan.FromMilliseconds(perScanMs - 30) * V3HandlerScans.For(Command.Read)) + TimeSpan.FromMilliseconds(perScanMs - 100);
        (after - before).Should().Be(expected);
    }

    [Fact]
    public async Task Exchange_Refusal_IsAnErrorResponseWithV2sCode()
    {
        var (link, _) = Create(request => [Codec.Encode(new Reply(ReplyStatus.NotWritable, Codec.RequestCheckOf(request), []))]);

        var reply = await link.ExchangeAsync(new WriteBitRequest(Two, ProtocolArea.I, 0, 1, true), default);

        reply.Response.Should().BeOfType<ErrorResponse>().Which.Error.Should().Be(ProtocolError.NotWritable);
    }

    [Fact]
    public async Task Exchange_ReadOfTwoRanges_FailsBeforeAnythingIsSent()
    {
        var (link, station) = Create(_ => null);

        var reply = await link.ExchangeAsync(new ReadRequest(Two, [new ReadItem(ProtocolArea.M, 0, 1), new ReadItem(ProtocolArea.V, 0, 1)]), default);

        var failed = reply.Should().BeOfType<LinkReply.Failed>().Subject;
        failed.Sent.Should().BeFalse();
        failed.Failure.Message.Should().Contain("has no protocol v3 form");
        station.Received.Should().BeEmpty();
    }

    [Fact]
    public async Task Exchange_DeviceVanishedAndBack_ReportedReconnectingThenReopened()
    {
        var clock = new ManualTimeProvider();
        var station = new Responder(request => [Codec.Encode(new Reply(ReplyStatus.Ok, Codec.RequestCheckOf(request), [0x42]))], clock);
        var link = new V3Link(station, new LinkOptions { Serial = new SerialSettings { PortName = "fake", BaudRate = 9600 } }, clock);
        var read = new ReadRequest(Two, [new ReadItem(ProtocolArea.M, 0, 1)]);
        (await link.ExchangeAsync(read, default)).Response.Should().BeOfType<ReadResponse>();

        station.Present = false;
        var lost = await link.ExchangeAsync(read, default);
        station.Present = true;
        var back = await link.ExchangeAsync(read, default);

        lost.Failure!.Message.Should().Be("station 2: serial port fake: discard input failed: the device vanished - reconnecting");
        back.Response.Should().BeOfType<ReadResponse>().Which.Data.Should().Equal(0x42);
        link.Outage.Should().BeNull();
    }

    private static (V3Link Link, Responder Station) Create(Func<byte[], IEnumerable<byte[]>?> respond)
    {
        var clock = new ManualTimeProvider();
        var station = new Responder(respond, clock);
        var options = new LinkOptions { Serial = new SerialSettings { PortName = "fake", BaudRate = 9600 } };
        return (new V3Link(station, options, clock), station);
    }

    private sealed class BytesComparer : IEqualityComparer<byte[]>
    {
        public bool Equals(byte[]? x, byte[]? y) => x.AsSpan().SequenceEqual(y);

        public int GetHashCode(byte[] obj) => obj.Length;
    }

    /// <summary>A station behind a transport: each frame written gets the frames <c>respond</c> returns (none: silence, the clock runs out).</summary>
    private sealed class Responder(Func<byte[], IEnumerable<byte[]>?> respond, ManualTimeProvider clock) : ITransport
    {
        private readonly Queue<byte> _pending = new();

        public List<byte[]> Received { get; } = [];

        public string Name => "fake";

        public bool IsOpen { get; private set; }

        /// <summary>False: the device vanished (the port fails and cannot be opened).</summary>
        public bool Present { get; set; } = true;

        public Task OpenAsync(CancellationToken cancellationToken)
        {
            if (!Present)
            {
                throw new PlcCommunicationException(PlcErrorKind.PortUnavailable, null, "serial port fake: open failed: no such port");
            }

            IsOpen = true;
            return Task.CompletedTask;
        }

        public Task WriteAsync(ReadOnlyMemory<byte> data, CancellationToken cancellationToken)
        {
            var frame = data.ToArray();
            if (frame.Length > 1)
            {
                Received.Add(frame);
                foreach (var reply in respond(frame) ?? [])
                {
                    reply.ToList().ForEach(_pending.Enqueue);
                }
            }

            return Task.CompletedTask;
        }

        public Task<int> ReadAsync(Memory<byte> buffer, TimeSpan timeout, CancellationToken cancellationToken)
        {
            if (_pending.Count == 0)
            {
                clock.Advance(timeout);
                return Task.FromResult(0);
            }

            var count = 0;
            while (count < buffer.Length && _pending.Count > 0)
            {
                buffer.Span[count++] = _pending.Dequeue();
            }

            return Task.FromResult(count);
        }

        public void DiscardInput()
        {
            if (!Present)
            {
                IsOpen = false;
                throw new PlcCommunicationException(PlcErrorKind.PortUnavailable, null, "serial port fake: discard input failed: the device vanished");
            }

            _pending.Clear();
        }

        public ValueTask DisposeAsync() => ValueTask.CompletedTask;
    }
}
