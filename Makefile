# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

## The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

T# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

w# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

o# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

c# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

o# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

m# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

m# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

a# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

n# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

d# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

s# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

d# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

o# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

a# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

l# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

l# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

h# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

e# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

s# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

e# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

-# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

u# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

p# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

o# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

n# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

a# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

f# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

r# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

e# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

s# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

h# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

m# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

a# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

c# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

h# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

i# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

n# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

e# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

:# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

`# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

m# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

a# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

k# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

e# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

d# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

e# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

m# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

o# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

`# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

a# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

n# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

d# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

`# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

m# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

a# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

k# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

e# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

e# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

s# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

`# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

.# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo


# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

P# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

Y# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

T# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

H# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

O# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

N# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

?# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

=# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

p# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

y# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

h# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

o# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

n# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

3# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo


# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

V# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

E# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

N# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

V# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

:# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

=# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

.# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

v# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

e# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

n# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

v# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo


# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

B# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

I# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

N# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

:# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

=# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

$# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

(# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

V# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

E# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

N# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

V# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

)# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

/# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

b# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

i# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

n# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo


# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo


# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

.# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

P# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

H# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

O# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

N# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

Y# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

:# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

d# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

e# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

m# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

o# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

e# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

s# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

b# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

e# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

n# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

c# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

h# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

c# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

l# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

e# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

a# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

n# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo


# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo


# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

$# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

(# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

B# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

I# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

N# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

)# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

/# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

p# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

y# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

h# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

o# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

n# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

:# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo


# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

	# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

$# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

(# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

P# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

Y# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

T# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

H# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

O# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

N# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

)# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

-# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

m# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

v# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

e# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

n# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

v# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

$# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

(# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

V# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

E# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

N# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

V# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

)# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo


# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

	# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

$# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

(# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

B# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

I# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

N# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

)# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

/# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

p# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

y# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

h# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

o# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

n# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

-# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

m# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

p# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

i# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

p# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

i# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

n# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

s# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

a# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

l# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

l# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

-# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

-# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

q# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

u# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

i# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

e# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

-# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

-# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

u# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

p# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

g# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

r# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

a# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

d# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

e# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

p# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

i# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

p# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo


# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo


# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

$# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

(# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

V# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

E# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

N# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

V# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

)# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

/# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

.# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

i# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

n# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

s# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

a# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

l# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

l# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

e# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

d# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

:# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

p# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

y# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

p# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

r# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

o# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

j# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

e# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

c# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

.# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

o# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

m# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

l# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

|# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

$# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

(# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

B# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

I# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

N# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

)# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

/# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

p# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

y# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

h# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

o# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

n# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo


# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

	# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

$# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

(# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

B# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

I# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

N# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

)# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

/# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

p# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

y# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

h# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

o# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

n# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

-# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

m# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

p# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

i# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

p# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

i# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

n# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

s# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

a# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

l# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

l# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

-# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

-# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

q# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

u# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

i# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

e# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

-# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

e# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

.# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo


# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

	# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

o# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

u# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

c# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

h# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

$# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

@# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo


# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo


# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

$# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

(# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

V# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

E# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

N# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

V# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

)# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

/# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

.# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

i# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

n# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

s# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

a# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

l# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

l# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

e# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

d# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

-# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

e# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

s# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

:# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

p# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

y# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

p# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

r# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

o# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

j# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

e# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

c# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

.# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

o# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

m# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

l# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

|# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

$# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

(# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

B# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

I# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

N# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

)# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

/# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

p# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

y# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

h# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

o# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

n# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo


# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

	# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

$# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

(# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

B# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

I# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

N# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

)# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

/# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

p# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

y# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

h# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

o# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

n# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

-# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

m# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

p# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

i# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

p# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

i# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

n# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

s# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

a# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

l# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

l# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

-# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

-# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

q# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

u# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

i# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

e# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

-# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

e# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

"# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

.# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

[# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

e# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

s# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

]# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

"# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo


# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

	# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

o# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

u# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

c# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

h# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

$# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

@# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

$# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

(# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

V# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

E# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

N# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

V# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

)# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

/# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

.# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

i# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

n# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

s# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

a# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

l# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

l# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

e# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

d# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo


# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo


# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

## The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

A# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

s# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

i# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

m# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

u# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

l# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

a# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

e# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

d# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

b# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

e# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

n# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

c# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

h# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

r# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

u# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

n# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

o# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

f# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

h# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

e# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

p# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

a# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

p# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

e# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

r# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

'# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

s# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

p# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

r# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

o# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

o# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

y# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

p# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

e# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

(# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

v# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

i# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

r# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

u# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

a# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

l# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

c# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

l# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

o# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

c# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

k# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

:# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

s# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

e# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

c# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

o# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

n# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

d# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

s# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

)# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

,# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

h# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

e# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

n# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

i# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

s# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

v# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

a# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

l# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

i# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

d# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

a# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

i# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

o# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

n# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo


# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

## The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

r# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

e# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

p# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

o# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

r# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

;# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

h# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

e# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

l# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

a# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

s# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

l# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

i# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

n# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

e# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

p# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

r# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

i# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

n# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

e# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

d# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

i# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

s# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

h# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

e# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

p# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

a# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

h# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

o# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

f# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

r# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

e# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

p# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

o# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

r# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

.# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

h# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

m# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

l# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

.# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo


# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

d# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

e# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

m# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

o# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

:# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

$# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

(# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

V# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

E# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

N# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

V# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

)# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

/# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

.# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

i# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

n# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

s# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

a# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

l# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

l# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

e# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

d# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo


# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

	# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

o# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

u# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

=# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

$# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

$# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

(# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

$# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

(# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

B# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

I# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

N# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

)# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

/# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

m# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

k# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

m# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

a# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

c# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

q# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

u# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

i# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

r# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

e# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

-# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

-# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

b# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

a# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

c# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

k# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

e# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

n# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

d# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

s# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

i# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

m# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

-# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

-# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

c# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

l# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

o# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

c# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

k# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

v# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

i# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

r# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

u# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

a# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

l# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

-# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

-# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

o# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

u# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

r# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

e# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

p# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

o# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

r# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

s# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

/# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

d# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

e# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

m# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

o# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

-# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

r# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

u# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

n# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

s# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

)# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

|# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

|# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

e# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

x# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

i# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

1# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

;# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

\# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo


# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

	# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

r# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

u# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

n# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

=# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

$# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

$# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

(# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

p# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

r# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

i# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

n# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

f# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

'# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

%# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

s# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

\# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

n# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

'# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

"# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

$# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

$# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

o# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

u# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

"# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

|# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

a# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

i# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

l# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

-# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

n# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

1# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

)# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

;# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

\# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo


# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

	# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

$# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

(# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

B# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

I# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

N# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

)# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

/# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

m# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

k# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

m# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

r# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

e# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

p# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

o# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

r# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

"# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

$# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

$# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

r# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

u# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

n# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

"# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

-# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

-# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

o# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

u# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

r# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

e# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

p# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

o# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

r# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

s# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

/# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

d# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

e# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

m# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

o# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo


# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo


# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

e# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

s# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

:# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

$# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

(# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

V# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

E# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

N# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

V# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

)# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

/# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

.# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

i# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

n# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

s# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

a# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

l# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

l# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

e# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

d# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

-# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

e# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

s# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo


# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

	# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

$# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

(# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

B# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

I# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

N# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

)# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

/# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

r# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

u# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

f# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

f# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

c# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

h# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

e# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

c# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

k# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

.# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo


# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

	# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

$# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

(# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

B# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

I# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

N# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

)# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

/# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

l# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

i# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

n# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

-# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

i# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

m# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

p# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

o# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

r# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

s# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo


# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

	# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

O# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

P# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

E# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

N# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

B# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

L# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

A# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

S# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

_# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

N# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

U# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

M# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

_# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

T# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

H# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

R# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

E# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

A# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

D# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

S# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

=# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

1# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

O# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

M# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

P# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

_# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

N# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

U# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

M# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

_# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

T# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

H# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

R# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

E# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

A# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

D# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

S# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

=# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

1# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

$# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

(# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

B# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

I# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

N# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

)# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

/# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

p# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

y# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

h# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

o# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

n# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

-# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

m# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

p# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

y# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

e# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

s# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

-# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

q# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo


# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo


# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

b# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

e# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

n# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

c# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

h# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

:# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

$# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

(# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

V# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

E# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

N# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

V# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

)# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

/# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

.# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

i# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

n# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

s# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

a# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

l# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

l# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

e# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

d# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

-# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

e# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

s# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo


# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

	# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

$# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

(# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

B# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

I# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

N# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

)# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

/# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

p# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

y# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

h# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

o# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

n# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

-# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

m# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

p# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

i# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

p# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

i# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

n# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

s# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

a# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

l# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

l# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

-# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

-# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

q# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

u# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

i# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

e# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

-# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

e# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

"# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

.# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

[# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

b# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

e# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

n# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

c# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

h# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

]# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

"# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo


# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

	# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

f# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

o# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

r# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

f# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

i# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

n# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

b# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

e# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

n# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

c# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

h# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

m# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

a# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

r# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

k# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

s# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

/# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

b# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

e# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

n# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

c# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

h# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

_# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

*# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

.# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

p# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

y# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

;# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

d# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

o# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

$# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

(# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

B# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

I# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

N# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

)# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

/# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

p# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

y# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

h# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

o# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

n# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

$# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

$# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

f# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

|# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

|# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

e# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

x# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

i# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

t# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

1# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

;# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

d# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

o# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

n# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

e# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo


# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo


# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

c# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

l# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

e# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

a# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

n# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

:# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo


# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

	# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

r# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

m# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

-# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

r# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

f# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

$# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

(# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

V# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

E# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

N# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

V# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

)# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

b# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

u# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

i# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

l# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

d# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

 # The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

*# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

.# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

e# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

g# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

g# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

-# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

i# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

n# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

f# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

o# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo


# The paper's two tests (eps 0 and 12.2 %) on the simulated bench (virtual clock: seconds) and
# one validation report of both, under ./mkm-out/demo; the last line printed is report.html.
demo: $(VENV)/.installed
	$(BIN)/mkm demo

