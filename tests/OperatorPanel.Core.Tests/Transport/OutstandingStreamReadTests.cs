using OperatorPanel.Core.Transport;

namespace OperatorPanel.Core.Tests.Transport;

/// <summary>The read request stays outstanding across timeouts, so bytes that come late are handed out, never lost.</summary>
public sealed class OutstandingStreamReadTests
{
    [Fact]
    public void Read_NothingYet_ReturnsZeroAndKeepsOneRequestOutstanding()
    {
        var stream = new ScriptedReadStream();
        var reader = new OutstandingStreamRead(stream);

        reader.Read(new byte[8], TimeSpan.Zero, default).Should().Be(0);
        reader.Read(new byte[8], TimeSpan.Zero, default).Should().Be(0);

        stream.Requests.Should().Be(1);
    }

    [Fact]
    public void Read_BytesArriveAfterATimeout_NextReadHandsThemOut()
    {
        var stream = new ScriptedReadStream();
        var reader = new OutstandingStreamRead(stream);
        reader.Read(new byte[8], TimeSpan.Zero, default);

        stream.Complete("<01>"u8);
        var buffer = new byte[8];
        var count = reader.Read(buffer, TimeSpan.FromSeconds(5), default);

        buffer[..count].Should().Equal("<01>"u8.ToArray());
    }

    [Fact]
    public void Read_MoreBytesThanTheBuffer_RestComesWithTheNextRead()
    {
        var stream = new ScriptedReadStream();
        var reader = new OutstandingStreamRead(stream);
        reader.Read(new byte[1], TimeSpan.Zero, default);
        stream.Complete("<0102>"u8);

        var first = new byte[4];
        var second = new byte[8];
        reader.Read(first, TimeSpan.FromSeconds(5), default).Should().Be(4);
        var rest = reader.Read(second, TimeSpan.FromSeconds(5), default);

        first.Should().Equal("<010"u8.ToArray());
        second[..rest].Should().Equal("2>"u8.ToArray());
    }

    [Fact]
    public void Discard_BytesTakenButNotHandedOut_AreDropped()
    {
        var stream = new ScriptedReadStream();
        var reader = new OutstandingStreamRead(stream);
        reader.Read(new byte[1], TimeSpan.Zero, default);
        stream.Complete("<0102>"u8);
        reader.Read(new byte[2], TimeSpan.FromSeconds(5), default);

        reader.Discard();

        reader.Read(new byte[8], TimeSpan.Zero, default).Should().Be(0);
    }

    [Fact]
    public void Read_StreamFails_RethrowsTheStreamsException()
    {
        var stream = new ScriptedReadStream();
        var reader = new OutstandingStreamRead(stream);
        reader.Read(new byte[1], TimeSpan.Zero, default);

        stream.Fail(new IOException("Input/output error", 5));

        reader.Invoking(r => r.Read(new byte[1], TimeSpan.FromSeconds(5), default))
            .Should().Throw<IOException>().Which.HResult.Should().Be(5);
    }

    /// <summary>A stream whose one outstanding read the test completes, as the serial library's I/O loop would.</summary>
    private sealed class ScriptedReadStream : Stream
    {
        private TaskCompletionSource<int>? _request;
        private byte[] _buffer = [];

        public int Requests { get; private set; }

        public override bool CanRead => true;

        public override bool CanSeek => false;

        public override bool CanWrite => false;

        public override long Length => throw new NotSupportedException();

        public override long Position { get => throw new NotSupportedException(); set => throw new NotSupportedException(); }

        public void Complete(ReadOnlySpan<byte> bytes)
        {
            bytes.CopyTo(_buffer);
            _request!.SetResult(bytes.Length);
        }

        public void Fail(Exception failure) => _request!.SetException(failure);

        public override Task<int> ReadAsync(byte[] buffer, int offset, int count, CancellationToken cancellationToken)
        {
            Requests++;
            _buffer = buffer;
            _request = new TaskCompletionSource<int>(TaskCreationOptions.RunContinuationsAsynchronously);
            return _request.Task;
        }

        public override ValueTask<int> ReadAsync(Memory<byte> buffer, CancellationToken cancellationToken = default) => throw new NotSupportedException();

        public override int Read(byte[] buffer, int offset, int count) => throw new NotSupportedException();

        public override void Flush() => throw new NotSupportedException();

        public override long Seek(long offset, SeekOrigin origin) => throw new NotSupportedException();

        public override void SetLength(long value) => throw new NotSupportedException();

        public override void Write(byte[] buffer, int offset, int count) => throw new NotSupportedException();
    }
}
