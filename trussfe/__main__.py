from .cli import run

# guarded: worker processes started by spawning (the study command's Dask workers) import
# this module as ``__mp_main__`` and must not run the command line again
if __name__ == "__main__":
    run()
